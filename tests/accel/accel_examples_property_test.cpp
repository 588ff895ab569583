// Every example scene (examples/*.toml) through every accelerator: the default BVH answers as brute
// force on adversarial rays over the scene's whole geometry (the hit bit for bit), and the BVH and
// the kd-trees render the same image byte for byte (a small frame, one sample a pixel, so that the
// suite stays fast; the full-size identity on a gmsh part is accel_image_identity_test.cpp's).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/accel_test_geometry.hpp"
#include "support/test_images.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

std::vector<std::filesystem::path> exampleScenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(LANCER_SOURCE_DIR "/examples")) {
    if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(AccelExamples, EveryExampleAnswersAsBruteForceAndRendersAlikeOnEveryTree) {
  const std::vector<std::filesystem::path> scenes = exampleScenes();
  ASSERT_GE(scenes.size(), 5u);
  for (const std::filesystem::path& path : scenes) {
    SCOPED_TRACE(path.filename().string());
    SceneDescription d = loadScene(path.string());
    d.render.width = 48;
    d.render.height = 36;
    d.render.samples = 1;
    const Scene scene = buildScene(d);
    const test::Soup soup{scene.geometry.positions, scene.geometry.faces};
    ASSERT_FALSE(soup.faces.empty());
    const NaiveAccel naive(soup.positions, soup.faces);
    const Bvh bvh = Bvh::build(soup.positions, soup.faces);
    const KdTree planes = KdTree::buildSah(soup.positions, soup.faces);
    std::mt19937 rng(31);
    int differences = 0, hits = 0;
    const std::vector<test::TestRay> rays = test::adversarialRays(soup, planes, rng, 800);
    for (const test::TestRay& r : rays) {
      Hit expected, actual;
      const bool expectHit = naive.intersect(r.ray, r.tMin, r.tMax, expected);
      hits += expectHit;
      const bool same = bvh.intersect(r.ray, r.tMin, r.tMax, actual) == expectHit &&
                        (!expectHit || test::sameBits(actual, expected)) &&
                        bvh.occluded(r.ray, r.tMin, r.tMax) == naive.occluded(r.ray, r.tMin, r.tMax);
      if (!same) ++differences;
    }
    EXPECT_EQ(differences, 0) << "of " << rays.size() << " rays";
    EXPECT_GT(hits, static_cast<int>(rays.size()) / 10);
    const Image reference = test::renderScene(d, scene, AccelKind::Bvh, 2);
    for (AccelKind kind : {AccelKind::KdTreeSah, AccelKind::KdTreeSahExact, AccelKind::KdTreeMedian}) {
      SCOPED_TRACE(std::string(accelKindName(kind)));
      EXPECT_EQ(test::differingPixels(test::renderScene(d, scene, kind, 2), reference), 0);
    }
  }
}

}  // namespace
}  // namespace lancer
