// Golden image of a cut multi-material part: gmsh tetrahedra of three physical volumes meshed
// together (a housing around a bushing around a shaft, tests/data/multimaterial/three_materials.geo),
// cut through the axis by a capped plane. Regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

const std::string kDataDir = LANCER_TEST_DATA_DIR "/multimaterial/";

TEST(MultiMaterialGolden, CutPartShowsEachVolumesCapInItsMaterial) {
  test::expectImageNear(test::renderScene(loadScene(kDataDir + "cut_three_materials.toml")),
                        kDataDir + "golden/cut_three_materials.png", test::kRenderGoldenMinPsnrDb);
}

TEST(MultiMaterialGolden, TheGoldenTellsAMissingCapAndAVolumeInAnotherMaterial) {
  // Guards the golden itself: without caps, or with the bushing in the housing's material (an
  // interface that lost its second volume), the PSNR must fall below the floor.
  auto uncapped = [](SceneDescription& d) { d.clips[0].cap = false; };
  auto bushingInHousing = [](SceneDescription& d) {
    for (GroupMaterial& group : d.meshes[0].groupMaterials)
      if (group.group == "Bushing") group.material = d.meshes[0].material;
  };
  test::expectEachChangeBelowGoldenFloor(loadScene(kDataDir + "cut_three_materials.toml"),
                                         {uncapped, bushingInHousing});
}

}  // namespace
}  // namespace lancer
