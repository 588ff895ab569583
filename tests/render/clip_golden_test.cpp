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

const std::string kDataDir = LANCER_TEST_DATA_DIR "/render/";

TEST(ClipGolden, CappedCutsOfTwoVolumesInTheirGroupsColours) {
  const SceneDescription description = loadScene(kDataDir + "cut_bushing.toml");
  ASSERT_EQ(description.clips.size(), 1u);
  ASSERT_EQ(description.meshes.at(0).clips.size(), 1u);
  test::expectImageNear(test::renderScene(description), kDataDir + "golden/cut_bushing.png",
                        test::kRenderGoldenMinPsnrDb);
}

TEST(ClipGolden, EachCapChangesThePictureBeyondTheFloor) {
  // Guards the golden itself: with either cap off the hollow inside shows instead, and the PSNR
  // floor must tell that apart, or a renderer that lost that cap would still pass.
  test::expectEachChangeBelowGoldenFloor(loadScene(kDataDir + "cut_bushing.toml"),
                                         {[](SceneDescription& d) { d.clips[0].cap = false; },
                                          [](SceneDescription& d) { d.meshes[0].clips[0].cap = false; }});
}

}  // namespace
}  // namespace lancer
