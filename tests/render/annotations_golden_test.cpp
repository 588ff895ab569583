// Golden images of annotations: a banded field with isolines and its legend drawn in the picture,
// and a legend image with a title, units and labels in powers of ten.
#include <gtest/gtest.h>

#include "lancer/image/legend.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

TEST(AnnotationsGolden, BandsIsolinesAndLegend) {
  const SceneDescription description = loadScene(test::dataFile("render/annotated_square.toml"));
  const Scene scene = buildScene(description);
  ASSERT_TRUE(scene.fieldColors);
  ASSERT_EQ(scene.fieldColors->legendPlacement, LegendPlacement::Right);
  Image image = test::renderScene(description, scene);
  drawLegends(image, scene.fieldColors->legends, scene.fieldColors->legendPlacement, false);
  test::expectImageNear(image, test::dataFile("render/golden/annotated_square.png"),
                        test::kRenderGoldenMinPsnrDb);
}

TEST(AnnotationsGolden, LegendWithTitleUnitsAndPowersOfTen) {
  const LegendSpec spec{ColorMapKind::Coolwarm, -2.0e5, 3.5e5, "von Mises stress", "Pa", 0};
  test::expectImageNear(legendImage(spec, false, 160, 12, false),
                        test::dataFile("render/golden/legend_vertical.png"), test::kRenderGoldenMinPsnrDb);
  test::expectImageNear(legendImage(spec, true, 200, 12, false),
                        test::dataFile("render/golden/legend_horizontal.png"), test::kRenderGoldenMinPsnrDb);
}

}  // namespace
}  // namespace lancer
