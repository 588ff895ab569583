// Golden image of a field-coloured part: a gmsh-made square with the field x + 2 y, tilted and lit,
// coloured with magma over a given range. Regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include "lancer/image/color_map.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

TEST(FieldColorGolden, TiltedSquare) {
  SceneDescription description = loadScene(test::dataFile("render/field_square.toml"));
  description.render.srgb = false;  // the golden holds the linear encoding's raw values
  const Scene scene = buildScene(description);
  ASSERT_TRUE(scene.fieldColors);
  EXPECT_EQ(scene.fieldColors->legends.at(0).map, ColorMapKind::Magma);
  EXPECT_EQ(scene.fieldColors->legends.at(0).low, 0.5);
  test::expectImageNear(test::renderScene(description, scene),
                        test::dataFile("render/golden/field_square.png"), test::kRenderGoldenMinPsnrDb);
}

}  // namespace
}  // namespace lancer
