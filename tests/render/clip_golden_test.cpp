// Golden image of a cut view of a volume mesh: gmsh tetrahedra of two physical volumes (a sleeve with
// a cross hole around a separate shaft, tests/data/render/cut_bushing.geo) cut by a capped scene plane
// and a capped plane of that mesh only, over a floor. Regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// 8-bit PSNR floor, as for the other render goldens: a one-step difference everywhere stays far
// above it; a missing cap, a cap in the wrong group's colour or a moved plane falls far below.
constexpr double kMinPsnrDb = 40.0;

const std::string kDataDir = LANCER_TEST_DATA_DIR "/render/";

Image render(const SceneDescription& description) { return test::renderScene(description); }

TEST(ClipGolden, CappedCutsOfTwoVolumesInTheirGroupsColours) {
  const SceneDescription description = loadScene(kDataDir + "cut_bushing.toml");
  ASSERT_EQ(description.clips.size(), 1u);
  ASSERT_EQ(description.meshes.at(0).clips.size(), 1u);
  test::expectImageNear(render(description), kDataDir + "golden/cut_bushing.png", kMinPsnrDb);
}

TEST(ClipGolden, EachCapChangesThePictureBeyondTheFloor) {
  // Guards the golden itself: with either cap off the hollow inside shows instead, and the PSNR
  // floor must tell that apart, or a renderer that lost that cap would still pass.
  const SceneDescription description = loadScene(kDataDir + "cut_bushing.toml");
  const Image capped = render(description);
  SceneDescription sceneCapOff = description;
  sceneCapOff.clips[0].cap = false;
  EXPECT_LT(test::psnr8(render(sceneCapOff), capped), kMinPsnrDb);
  SceneDescription meshCapOff = description;
  meshCapOff.meshes[0].clips[0].cap = false;
  EXPECT_LT(test::psnr8(render(meshCapOff), capped), kMinPsnrDb);
}

}  // namespace
}  // namespace lancer
