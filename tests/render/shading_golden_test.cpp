// Golden images of the render core: each shading mode on a coarse gmsh sphere over a floor of quads
// (perspective, two lights, shadows), and an orthographic 3/4 view of a gmsh part with a group
// material. Scenes and meshes are in tests/data/render; regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// 8-bit PSNR floor: differences of about one 8-bit step everywhere stay far above it, a shifted
// shadow or a wrong normal falls far below.
constexpr double kMinPsnrDb = 40.0;

const std::string kDataDir = LANCER_TEST_DATA_DIR "/render/";

Image renderSceneFile(const std::string& sceneFile, ShadingMode shading, AccelKind accel = AccelKind::KdTreeSah) {
  SceneDescription description = loadScene(kDataDir + sceneFile);
  description.render.shading = shading;
  const Scene scene = buildScene(description);
  return test::renderScene(description, scene, accel);
}

TEST(ShadingGolden, FlatSphereShowsItsFacets) {
  test::expectImageNear(renderSceneFile("ball_on_floor.toml", ShadingMode::Flat), kDataDir + "golden/ball_flat.png",
                        kMinPsnrDb);
}

TEST(ShadingGolden, GouraudSphere) {
  test::expectImageNear(renderSceneFile("ball_on_floor.toml", ShadingMode::Gouraud),
                        kDataDir + "golden/ball_gouraud.png", kMinPsnrDb);
}

TEST(ShadingGolden, PhongSphere) {
  test::expectImageNear(renderSceneFile("ball_on_floor.toml", ShadingMode::Phong), kDataDir + "golden/ball_phong.png",
                        kMinPsnrDb);
}

TEST(ShadingGolden, OrthographicPartWithGroupMaterial) {
  test::expectImageNear(renderSceneFile("bracket_ortho.toml", ShadingMode::Phong),
                        kDataDir + "golden/bracket_ortho.png", kMinPsnrDb);
}

TEST(ShadingGolden, ShadingModesReallyDiffer) {
  // Guards the goldens themselves: the PSNR floor must be able to tell the modes apart, or a mode
  // that silently fell back to another would still pass its golden.
  const Image flat = renderSceneFile("ball_on_floor.toml", ShadingMode::Flat);
  const Image gouraud = renderSceneFile("ball_on_floor.toml", ShadingMode::Gouraud);
  const Image phong = renderSceneFile("ball_on_floor.toml", ShadingMode::Phong);
  EXPECT_LT(test::psnr8(flat, phong), kMinPsnrDb);
  EXPECT_LT(test::psnr8(gouraud, phong), kMinPsnrDb);
  EXPECT_LT(test::psnr8(flat, gouraud), kMinPsnrDb);
}

TEST(ShadingGolden, BruteForceRendersTheSameImage) {
  const Image kdTree = renderSceneFile("bracket_ortho.toml", ShadingMode::Phong, AccelKind::KdTreeSah);
  const Image naive = renderSceneFile("bracket_ortho.toml", ShadingMode::Phong, AccelKind::Naive);
  EXPECT_TRUE(kdTree == naive);
}

}  // namespace
}  // namespace lancer
