// The renderer's packets (primary rays of 4x2 pixels and their shadow rays, Tracer::tracePrimaries)
// give the image single rays give, byte for byte, on every example scene (clip planes, per-mesh cuts
// with caps, shadow catcher, glass, mirrors, edges and outlines, both samplers) at 1 and 3 threads;
// and the default BVH's image is the kd-tree's, byte for byte.
#include <gtest/gtest.h>

#include <string>

#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

Image render(const SceneDescription& description, const Scene& scene, const Accelerator& accelerator,
             bool packets, int threads, RenderStats* stats = nullptr) {
  const Camera camera = makeCamera(description.camera, scene, description.render);
  RenderOptions options;
  options.threads = threads;
  options.packets = packets;
  return Renderer(scene, accelerator, camera, description.render).renderImage(options, stats);
}

class PacketRenderIdentity : public testing::TestWithParam<const char*> {};

TEST_P(PacketRenderIdentity, PacketsAndSingleRaysRenderTheSameBytes) {
  SceneDescription description = loadScene(std::string(LANCER_SOURCE_DIR "/examples/") + GetParam());
  // Small, with a width and height that leave partial 4x2 blocks at the tiles' edges.
  const int width = description.render.width, height = description.render.height;
  description.render.width = 133;
  description.render.height = std::max(1, 133 * height / width) | 1;
  const Scene scene = buildScene(description);
  const Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, kDefaultAccel);
  RenderStats singleStats, packetStats;
  const Image single = render(description, scene, accelerator, false, 1, &singleStats);
  const Image packets = render(description, scene, accelerator, true, 1, &packetStats);
  ASSERT_EQ(single.width(), packets.width());
  ASSERT_EQ(single.height(), packets.height());
  EXPECT_EQ(test::differingPixels(single, packets), 0);
  EXPECT_EQ(singleStats.rays, packetStats.rays) << "the same rays, counted alike";
  EXPECT_EQ(singleStats.samplesPerPixel, packetStats.samplesPerPixel);
  EXPECT_EQ(test::differingPixels(single, render(description, scene, accelerator, true, 3)), 0)
      << "3 threads";
  // Every accelerator renders the example's bytes (the BVH is the default, the kd-tree the original one).
  const Accelerator kdTree =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
  EXPECT_EQ(test::differingPixels(single, render(description, scene, kdTree, true, 2)), 0)
      << "kd-tree, packets";
  EXPECT_EQ(test::differingPixels(single, render(description, scene, kdTree, false, 1)), 0)
      << "kd-tree, single rays";
}

INSTANTIATE_TEST_SUITE_P(Examples, PacketRenderIdentity,
                         testing::Values("demo.toml", "glass_and_mirror.toml", "cut_multimaterial.toml",
                                         "cut_per_mesh.toml", "cut_view.toml", "field.toml",
                                         "shadow_catcher.toml", "sphere.toml", "technical_view.toml"),
                         [](const testing::TestParamInfo<const char*>& example) {
                           const std::string name = example.param;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace lancer
