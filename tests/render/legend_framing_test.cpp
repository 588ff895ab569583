// Legends never cover the model: the automatic camera frames it in the part of the picture the
// legends leave (a flat model straight on, a solid from its 3/4 view); one legend per field, map and
// range however many annotations use it; titles that say the component.
#include <gtest/gtest.h>

#include <string>

#include "lancer/image/legend.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// The quick look of `file` coloured by `field` (`component` of it), through the preparation the
// command line uses, with `overrides` (the legend, arrows, ...).
PreparedRender quickLook(const std::string& file, const std::string& field, RenderOverrides overrides,
                         FieldComponent component = {}) {
  const std::string path = test::dataFile(file);
  const Mesh mesh = readMsh(path);
  RenderRequest request;
  request.description = quickLookScene(path, mesh);
  if (!field.empty()) {  // else not coloured
    ColorBy colorBy;
    colorBy.field = field;
    colorBy.component = component;
    request.description.meshes[0].colorBy = colorBy;
  }
  request.quickLookMesh = mesh;
  request.overrides = std::move(overrides);
  return prepareRender(std::move(request));
}

// Every vertex of the scene lies in the picture and outside the legends' side of it.
void expectModelBesideLegends(const PreparedRender& prepared) {
  const RenderSettings& settings = prepared.settings();
  const FieldColors& fields = *prepared.scene.fieldColors;
  const int breadth = legendsBreadth(fields.legends, fields.legendPlacement, settings.width, settings.height);
  ASSERT_GT(breadth, 0);
  const bool right = fields.legendPlacement == LegendPlacement::Right;
  float reach = 0;  // how far the model comes towards the legends' edge
  for (const Vec3& p : prepared.scene.geometry.positions) {
    float x, y;
    ASSERT_TRUE(prepared.camera.project(p, x, y));
    EXPECT_GE(x, 0);
    EXPECT_GE(y, 0);
    reach = std::max(reach, right ? x : y);
  }
  const int edge = right ? settings.width - breadth : settings.height - breadth;
  EXPECT_LE(reach, edge);
  EXPECT_GT(reach, edge - 0.25 * edge);  // and the model still fills the part the legends leave
}

TEST(LegendFraming, AFlatModelSitsBesideALegendAtTheRight) {
  RenderOverrides overrides;
  overrides.width = 320;
  overrides.height = 200;
  overrides.legend = LegendPlacement::Right;
  expectModelBesideLegends(quickLook("getdp/magnet_v2_az.pos", "az", overrides));
}

TEST(LegendFraming, AFlatModelSitsAboveALegendAtTheBottom) {
  RenderOverrides overrides;
  overrides.width = 320;
  overrides.height = 200;
  overrides.legend = LegendPlacement::Bottom;
  expectModelBesideLegends(quickLook("getdp/magnet_v2_az.pos", "az", overrides));
}

TEST(LegendFraming, ASolidInPerspectiveSitsBesideItsLegends) {
  for (const LegendPlacement placement : {LegendPlacement::Right, LegendPlacement::Bottom}) {
    RenderOverrides overrides;
    overrides.width = 320;
    overrides.height = 180;
    overrides.legend = placement;
    const PreparedRender prepared = quickLook("results/cantilever.msh", "stress", overrides,
                                              FieldComponent{FieldComponent::Kind::VonMises, 0});
    EXPECT_EQ(prepared.camera.projection(), Projection::Perspective);
    const RenderSettings& settings = prepared.settings();
    const FieldColors& fields = *prepared.scene.fieldColors;
    const int breadth = legendsBreadth(fields.legends, placement, settings.width, settings.height);
    for (const Vec3& p : prepared.scene.geometry.positions) {
      float x, y;
      ASSERT_TRUE(prepared.camera.project(p, x, y));
      EXPECT_LE(placement == LegendPlacement::Right ? x : y,
                (placement == LegendPlacement::Right ? settings.width : settings.height) - breadth);
    }
  }
}

TEST(LegendFraming, TitlesSayTheComponent) {
  RenderOverrides overrides;
  overrides.width = 64;
  overrides.height = 48;
  const auto title = [&](const std::string& field, FieldComponent component) {
    return quickLook("results/cantilever.msh", field, overrides, component)
        .scene.fieldColors->legends.at(0)
        .title;
  };
  EXPECT_EQ(title("stress", {FieldComponent::Kind::VonMises, 0}), "stress (von Mises)");
  EXPECT_EQ(title("stress", {FieldComponent::Kind::Index, 1}), "stress (xy)");
  EXPECT_EQ(title("displacement", {}), "|displacement|");
  EXPECT_EQ(title("displacement", {FieldComponent::Kind::Index, 1}), "displacement (y)");
  EXPECT_EQ(quickLook("getdp/magnet_v2_az.pos", "az", overrides).scene.fieldColors->legends.at(0).title,
            "az");
}

TEST(LegendFraming, ArrowsOfTheColouringFieldShareItsLegend) {
  RenderOverrides overrides;
  overrides.width = 64;
  overrides.height = 48;
  overrides.legend = LegendPlacement::Right;
  overrides.annotations.push_back(arrowsOfField("displacement", SourceLocation{"--arrows"}));
  const PreparedRender same = quickLook("results/cantilever.msh", "displacement", overrides);
  ASSERT_EQ(same.scene.fieldColors->legends.size(), 1u);
  EXPECT_EQ(same.scene.fieldColors->legends[0].title, "|displacement|");
  // With a range of the mesh's own, the arrows take it too: still one legend, of that range.
  overrides.range = std::pair{0.0, 2.0};
  const PreparedRender ranged = quickLook("results/cantilever.msh", "displacement", overrides);
  ASSERT_EQ(ranged.scene.fieldColors->legends.size(), 1u);
  EXPECT_EQ(ranged.scene.fieldColors->legends[0].high, 2.0);
  // Arrows of another field than the colours' have a legend of their own.
  overrides.range.reset();
  const PreparedRender other = quickLook("results/cantilever.msh", "stress", overrides,
                                         FieldComponent{FieldComponent::Kind::VonMises, 0});
  ASSERT_EQ(other.scene.fieldColors->legends.size(), 2u);
  EXPECT_EQ(other.scene.fieldColors->legends[1].title, "|displacement|");
}

// A scene of the hexahedral cube (tests/data/volume/cube_hex.msh, the vector field u at its nodes)
// with `keys` in its [[mesh]], through the same preparation.
PreparedRender cubeScene(const std::string& keys, RenderOverrides overrides) {
  RenderRequest request;
  request.description =
      parseScene("[[mesh]]\nfile = \"cube_hex.msh\"\n" + keys, test::dataFile("volume/scene.toml"));
  request.overrides = std::move(overrides);
  return prepareRender(std::move(request));
}

TEST(LegendFraming, ArrowsAloneCarryTheLegend) {
  RenderOverrides overrides;
  overrides.width = 64;
  overrides.height = 48;
  overrides.legend = LegendPlacement::Right;
  overrides.annotations.push_back(arrowsOfField("displacement", SourceLocation{"--arrows"}));
  // A mesh that is not coloured, its arrows coloured by magnitude: their legend, where --legend says.
  const PreparedRender alone = quickLook("results/cantilever.msh", "", overrides);
  ASSERT_TRUE(alone.scene.fieldColors.has_value());
  ASSERT_EQ(alone.scene.fieldColors->legends.size(), 1u);
  EXPECT_EQ(alone.scene.fieldColors->legends[0].title, "|displacement|");
  EXPECT_EQ(alone.scene.fieldColors->legendPlacement, LegendPlacement::Right);
  // --range and --color-map reach them as they reach isosurfaces and field lines.
  overrides.range = std::pair{0.0, 2.0};
  overrides.colorMap = *ColorMap::named("coolwarm");
  const PreparedRender ranged = quickLook("results/cantilever.msh", "", overrides);
  ASSERT_EQ(ranged.scene.fieldColors->legends.size(), 1u);
  EXPECT_EQ(ranged.scene.fieldColors->legends[0].high, 2.0);
  EXPECT_EQ(ranged.scene.fieldColors->legends[0].map, *ColorMap::named("coolwarm"));

  // Arrows through the volume, the skin a ghost around them: uncoloured or coloured by their field,
  // one legend, the arrows' (the ghost paints nothing).
  RenderOverrides legend;
  legend.width = 64;
  legend.height = 48;
  legend.legend = LegendPlacement::Right;
  const std::string arrows = "arrows = { field = \"u\", grid = [2, 2, 2] }\n";
  for (const std::string& colours : {std::string(), std::string("color_by = { field = \"u\" }\n")}) {
    const PreparedRender grid = cubeScene(colours + arrows, legend);
    ASSERT_TRUE(grid.scene.fieldColors.has_value()) << colours;
    ASSERT_EQ(grid.scene.fieldColors->legends.size(), 1u) << colours;
    EXPECT_EQ(grid.scene.fieldColors->legends[0].title, "|u|") << colours;
    EXPECT_EQ(grid.scene.fieldColors->legendPlacement, LegendPlacement::Right) << colours;
  }
  // The scene's own legend, without --legend.
  legend.legend.reset();
  const PreparedRender own =
      cubeScene("color_by = { field = \"u\", legend = \"bottom\" }\n" + arrows, legend);
  ASSERT_EQ(own.scene.fieldColors->legends.size(), 1u);
  EXPECT_EQ(own.scene.fieldColors->legendPlacement, LegendPlacement::Bottom);
}

}  // namespace
}  // namespace lancer
