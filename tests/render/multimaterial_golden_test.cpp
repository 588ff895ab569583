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

// 8-bit PSNR floor, as for the other render goldens.
constexpr double kMinPsnrDb = 40.0;

const std::string kDataDir = LANCER_TEST_DATA_DIR "/multimaterial/";

Image render(const SceneDescription& description) { return test::renderScene(description); }

TEST(MultiMaterialGolden, CutPartShowsEachVolumesCapInItsMaterial) {
  test::expectImageNear(render(loadScene(kDataDir + "cut_three_materials.toml")),
                        kDataDir + "golden/cut_three_materials.png", kMinPsnrDb);
}

TEST(MultiMaterialGolden, TheGoldenTellsAMissingCapAndAVolumeInAnotherMaterial) {
  // Guards the golden itself: without caps, or with the bushing in the housing's material (an
  // interface that lost its second volume), the PSNR must fall below the floor.
  const SceneDescription description = loadScene(kDataDir + "cut_three_materials.toml");
  const Image expected = render(description);
  SceneDescription uncapped = description;
  uncapped.clips[0].cap = false;
  EXPECT_LT(test::psnr8(render(uncapped), expected), kMinPsnrDb);
  SceneDescription oneMaterial = description;
  for (GroupMaterial& group : oneMaterial.meshes[0].groupMaterials)
    if (group.group == "Bushing") group.material = oneMaterial.meshes[0].material;
  EXPECT_LT(test::psnr8(render(oneMaterial), expected), kMinPsnrDb);
}

}  // namespace
}  // namespace lancer
