// Golden images of the render core: each shading mode on a coarse gmsh sphere over a floor of quads
// (perspective, two lights, shadows), and an orthographic 3/4 view of a gmsh part with a group
// material. Scenes and meshes are in tests/data/render; regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

const std::string kDataDir = LANCER_TEST_DATA_DIR "/render/";

Image renderSceneFile(const std::string& sceneFile, ShadingMode shading,
                      AccelKind accel = AccelKind::KdTreeSah) {
  SceneDescription description = loadScene(kDataDir + sceneFile);
  description.render.shading = shading;
  const Scene scene = buildScene(description);
  return test::renderScene(description, scene, accel);
}

struct SphereCase {
  const char* name;  // ShadingGolden/ShadedSphere.MatchesItsGolden/<name>
  ShadingMode shading;
  const char* golden;  // in tests/data/render/golden
};

std::ostream& operator<<(std::ostream& out, const SphereCase& c) { return out << c.golden; }

class ShadedSphere : public testing::TestWithParam<SphereCase> {};

TEST_P(ShadedSphere, MatchesItsGolden) {
  test::expectImageNear(renderSceneFile("ball_on_floor.toml", GetParam().shading),
                        kDataDir + "golden/" + GetParam().golden, test::kRenderGoldenMinPsnrDb);
}

// Flat shading shows the sphere's facets; Gouraud and Phong differ in the highlights.
INSTANTIATE_TEST_SUITE_P(ShadingGolden, ShadedSphere,
                         testing::Values(SphereCase{"Flat", ShadingMode::Flat, "ball_flat.png"},
                                         SphereCase{"Gouraud", ShadingMode::Gouraud, "ball_gouraud.png"},
                                         SphereCase{"Phong", ShadingMode::Phong, "ball_phong.png"}),
                         [](const testing::TestParamInfo<SphereCase>& param) { return param.param.name; });

TEST(ShadingGolden, OrthographicPartWithGroupMaterial) {
  test::expectImageNear(renderSceneFile("bracket_ortho.toml", ShadingMode::Phong),
                        kDataDir + "golden/bracket_ortho.png", test::kRenderGoldenMinPsnrDb);
}

TEST(ShadingGolden, ShadingModesReallyDiffer) {
  // Guards the goldens themselves: the PSNR floor must be able to tell the modes apart, or a mode
  // that silently fell back to another would still pass its golden.
  const Image flat = renderSceneFile("ball_on_floor.toml", ShadingMode::Flat);
  const Image gouraud = renderSceneFile("ball_on_floor.toml", ShadingMode::Gouraud);
  const Image phong = renderSceneFile("ball_on_floor.toml", ShadingMode::Phong);
  EXPECT_LT(test::psnr8(flat, phong), test::kRenderGoldenMinPsnrDb);
  EXPECT_LT(test::psnr8(gouraud, phong), test::kRenderGoldenMinPsnrDb);
  EXPECT_LT(test::psnr8(flat, gouraud), test::kRenderGoldenMinPsnrDb);
}

TEST(ShadingGolden, BruteForceRendersTheSameImage) {
  const Image kdTree = renderSceneFile("bracket_ortho.toml", ShadingMode::Phong, AccelKind::KdTreeSah);
  const Image naive = renderSceneFile("bracket_ortho.toml", ShadingMode::Phong, AccelKind::Naive);
  EXPECT_TRUE(kdTree == naive);
}

}  // namespace
}  // namespace lancer
