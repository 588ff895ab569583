// Golden images of the optics: a mirror ball and a glass ball (Fresnel, absorption, adaptive
// anti-aliasing) over a checkerboard of quads; gmsh meshes from tests/data/optics/*.geo
// (scripts/make_optics_fixtures.sh). Regenerate the images with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// 8-bit PSNR floor: a one-step difference everywhere stays far above it; a reflection or a
// refraction that moves (wrong normal, wrong index, inward shell) falls far below.
constexpr double kMinPsnrDb = 38.0;

const std::string kDataDir = LANCER_TEST_DATA_DIR "/optics/";

Image renderSceneFile(const std::string& sceneFile) {
  const SceneDescription description = loadScene(kDataDir + sceneFile);
  return test::renderScene(description, buildScene(description));
}

TEST(OpticsGolden, MirrorBallOverCheckerboard) {
  test::expectImageNear(renderSceneFile("mirror_ball.toml"), kDataDir + "golden/mirror_ball.png", kMinPsnrDb);
}

TEST(OpticsGolden, GlassBallOverCheckerboard) {
  test::expectImageNear(renderSceneFile("glass_ball.toml"), kDataDir + "golden/glass_ball.png", kMinPsnrDb);
}

TEST(OpticsGolden, ExampleSceneBuildsWithItsSolidsOriented) {
  // examples/glass_and_mirror.toml (the README's picture): three balls and a block are solids,
  // the checkerboard is an open surface.
  const SceneDescription description = loadScene(LANCER_SOURCE_DIR "/examples/glass_and_mirror.toml");
  const Scene scene = buildScene(description);
  std::size_t solidFaces = 0;
  for (std::uint8_t solid : scene.geometry.faceBoundsSolid) solidFaces += solid;
  const std::size_t floorFaces = 400;  // 10 x 10 squares of 2 x 2 quads
  EXPECT_EQ(solidFaces, scene.geometry.faces.size() - floorFaces);
  EXPECT_EQ(description.render.sampler, SamplerKind::Adaptive);
}

}  // namespace
}  // namespace lancer
