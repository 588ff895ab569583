// A view set up in gmsh's GUI and saved with its options (tests/data/results/cantilever.msh.opt,
// written by gmsh through scripts/make_result_fixtures.py): the displacement view drawn as the
// deformed shape, the stress at its time step on the custom range, the hidden view left out.
#include "lancer/scene/results/gmsh_post_options.hpp"

#include <gtest/gtest.h>

#include <variant>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/scene.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

SceneDescription oneMesh() {
  SceneDescription description;
  MeshInstance mesh;
  mesh.file = test::dataFile("results/cantilever.msh");
  description.meshes.push_back(mesh);
  return description;
}

TEST(GmshPostOptions, ReadsTheViewsGmshSaved) {
  const std::vector<GmshPostView> views = readGmshPostViews(test::dataFile("results/cantilever.msh.opt"));
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[0].name, "displacement");
  EXPECT_EQ(views[0].vectorType, 5);
  EXPECT_EQ(views[0].displacementFactor, 3);
  EXPECT_EQ(views[1].rangeType, 2);
  EXPECT_EQ(views[1].customMin, 1);
  EXPECT_EQ(views[1].customMax, 4);
  EXPECT_EQ(views[1].timeStep, 2);
  EXPECT_EQ(views[1].intervalsType, 1);
  EXPECT_EQ(views[1].nbIso, 8);
  EXPECT_TRUE(views[1].visible);
  EXPECT_FALSE(views[2].visible);
}

TEST(GmshPostOptions, TheViewRendersAsSetUp) {
  const std::string path = test::dataFile("results/cantilever.msh.opt");
  SceneDescription description = oneMesh();
  applyGmshPostViews(description, readMsh(description.meshes[0].file), readGmshPostViews(path), path);
  const MeshInstance& mesh = description.meshes[0];
  ASSERT_TRUE(mesh.warp);
  EXPECT_EQ(mesh.warp->field, "displacement");
  EXPECT_EQ(mesh.warp->factor, 3);
  ASSERT_TRUE(mesh.colorBy);
  EXPECT_EQ(mesh.colorBy->field, "stress");
  EXPECT_EQ(mesh.colorBy->range, (std::pair<double, double>{1, 4}));
  EXPECT_EQ(description.when.step, 2);
  // IntervalsType = 1 with NbIso = 8: isolines of the stress at gmsh's 8 values over the colours'
  // range, ends included; ShowScale (gmsh's default): the legend along the bottom, as gmsh draws it.
  ASSERT_TRUE(mesh.isolines);
  EXPECT_EQ(mesh.isolines->field, "stress");
  EXPECT_EQ(mesh.isolines->count, 8);
  EXPECT_TRUE(mesh.isolines->colorRangeEnds);
  EXPECT_EQ(mesh.colorBy->bands, 0);
  EXPECT_EQ(mesh.colorBy->legend, LegendPlacement::Bottom);
}

TEST(GmshPostOptions, TheViewTakesGmshsColourMap) {
  // gmsh's default map (ColormapNumber 2, its jet) unless the view names another; ColormapSwap
  // reverses it. A mesh's own color_by keeps its map.
  const std::string path = test::dataFile("results/colormap.opt");
  const std::vector<GmshPostView> views = readGmshPostViews(path);
  ASSERT_EQ(views.size(), 3u);
  EXPECT_EQ(views[0].colormapNumber, 2);
  EXPECT_EQ(views[1].colormapNumber, 7);
  EXPECT_TRUE(views[1].colormapSwap);
  SceneDescription description = oneMesh();
  const Mesh mesh = readMsh(description.meshes[0].file);
  applyGmshPostViews(description, mesh, views, path);
  ASSERT_TRUE(description.meshes[0].colorBy);
  EXPECT_EQ(description.meshes[0].colorBy->map.name(), "gmsh:7_r");
  EXPECT_EQ(description.meshes[0].colorBy->map, *ColorMap::named("gmsh:7_r"));
  SceneDescription own = oneMesh();
  ColorBy colorBy;
  colorBy.field = "stress";
  colorBy.map = *ColorMap::named("RdBu");
  own.meshes[0].colorBy = colorBy;
  applyGmshPostViews(own, mesh, views, path);
  EXPECT_EQ(own.meshes[0].colorBy->map.name(), "RdBu");
}

// The description and scene of cantilever.msh under the options file `name` of tests/data/results.
struct AppliedView {
  SceneDescription description;
  Scene scene;
};
AppliedView applyOptions(const std::string& name) {
  const std::string path = test::dataFile("results/" + name);
  AppliedView applied{oneMesh(), {}};
  applied.description.render.width = applied.description.render.height = 32;
  const Mesh mesh = readMsh(applied.description.meshes[0].file);
  applyGmshPostViews(applied.description, mesh, readGmshPostViews(path), path);
  applied.scene = buildScene(applied.description, {mesh}, 1);
  return applied;
}

TEST(GmshPostOptions, IsoValuesAreIsolinesOfTheColouredFieldAtGmshsValues) {
  // View[1]: the stress (von Mises, gmsh's default for a tensor) on the custom range [1, 4] with
  // IntervalsType = 1 and NbIso = 8: lines at 1 + 3 k / 7 for k = 0..7, as gmsh's getScaleValue.
  const AppliedView applied = applyOptions("cantilever.msh.opt");
  EXPECT_EQ(applied.description.meshes[0].colorBy->component.kind, FieldComponent::Kind::VonMises);
  ASSERT_TRUE(applied.scene.isolines);
  ASSERT_EQ(applied.scene.isolines->styles.size(), 2u);  // style 0: faces without lines
  const std::vector<float>& values = applied.scene.isolines->styles[1].values;
  ASSERT_EQ(values.size(), 8u);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(values[static_cast<std::size_t>(k)], 1 + 3.0 * k / 7, 1e-6) << k;
  ASSERT_TRUE(applied.scene.fieldColors);
  EXPECT_EQ(applied.scene.fieldColors->legendPlacement, LegendPlacement::Bottom);
  // As gmsh draws iso-values: the lines in the map's colours at their values over [1, 4], the
  // surface in its own material (no face takes the field's colours), the legend kept.
  const std::vector<Vec3>& colors = applied.scene.isolines->styles[1].valueColors;
  ASSERT_EQ(colors.size(), 8u);
  const ColorMap& map = applied.description.meshes[0].colorBy->map;
  EXPECT_EQ(map.name(), "gmsh:2");  // gmsh's default map, ColormapNumber = 2
  for (int k = 0; k < 8; ++k)
    EXPECT_LT(length(colors[static_cast<std::size_t>(k)] - map(k / 7.0f)), 1e-5f) << k;
  for (const std::uint8_t faceMap : applied.scene.fieldColors->faceColorMap) ASSERT_EQ(faceMap, 0);
  ASSERT_EQ(applied.scene.fieldColors->legends.size(), 1u);
  EXPECT_EQ(applied.scene.fieldColors->legends[0].low, 1);
  EXPECT_EQ(applied.scene.fieldColors->legends[0].high, 4);
}

TEST(GmshPostOptions, GmshsIsoValuesIncludeBothEnds) {
  EXPECT_EQ(gmshIsoValues(0, 3, 3), (std::vector<double>{0, 1.5, 3}));
  EXPECT_EQ(gmshIsoValues(2, 4, 1), (std::vector<double>{3}));
}

TEST(GmshPostOptions, DiscreteIntervalsAreBandsAndShowScaleZeroHidesTheLegend) {
  // discrete.opt: the displacement hidden, the stress in IntervalsType = 3 with NbIso = 5 and
  // ShowScale = 0: 5 bands on the mesh, no isolines, no legend, no warp.
  const AppliedView applied = applyOptions("discrete.opt");
  const MeshInstance& mesh = applied.description.meshes[0];
  EXPECT_FALSE(mesh.warp);
  EXPECT_FALSE(mesh.isolines);
  ASSERT_TRUE(mesh.colorBy);
  EXPECT_EQ(mesh.colorBy->field, "stress");
  EXPECT_EQ(mesh.colorBy->bands, 5);
  ASSERT_TRUE(applied.scene.fieldColors);
  EXPECT_EQ(applied.scene.fieldColors->legendPlacement, LegendPlacement::None);
  ASSERT_FALSE(applied.scene.fieldColors->faceBands.empty());
  EXPECT_EQ(applied.scene.fieldColors->faceBands.front(), 5);
  EXPECT_FALSE(applied.scene.isolines);
}

TEST(GmshPostOptions, HiddenViewsColourNothing) {
  const AppliedView applied = applyOptions("hidden.opt");
  EXPECT_FALSE(applied.description.meshes[0].colorBy);
  EXPECT_FALSE(applied.description.meshes[0].warp);
  EXPECT_FALSE(applied.scene.fieldColors);
}

TEST(GmshPostOptions, OptionsOfViewsTheFileDoesNotHave) {
  const test::ScratchFolder folder;
  folder.write("a.opt", "View[5].RangeType = 3;\n");
  SceneDescription description = oneMesh();
  const Mesh mesh = readMsh(description.meshes[0].file);
  // The message of applying the options file `name` of the folder to the mesh.
  auto errorOf = [&](const std::string& name) {
    return test::messageOf([&] {
      applyGmshPostViews(description, mesh, readGmshPostViews(folder.file(name)), folder.file(name));
    });
  };
  auto expectContains = [](const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  expectContains(errorOf("a.opt"),
                 "a.opt:1:1: error: View[5] is set here, but " + description.meshes[0].file + " has 3 views");
  folder.write("b.opt", "View[1].Name = \"stress\";\nView[1].TimeStep = 6;\n");
  expectContains(errorOf("b.opt"), "View[1].TimeStep = 6, but the view \"stress\" of " +
                                       description.meshes[0].file + " has 4 steps: give 0 to 3");
  folder.write("c.opt", "View[0].NbIso = many;\n");
  EXPECT_NE(test::messageOf([&] {
              readGmshPostViews(folder.file("c.opt"));
            }).find("c.opt:1:16: error: View[0].NbIso should be a number, not 'many'"),
            std::string::npos)
      << test::messageOf([&] { readGmshPostViews(folder.file("c.opt")); });
}

TEST(GmshPostOptions, IntegersOutsideAnIntAreRefusedNotWrapped) {
  // TimeStep = 2^32 showed step 0.
  const test::ScratchFolder folder;
  folder.write("big.opt", "View[0].Name = \"stress\";\nView[0].TimeStep = 4294967296;\n");
  EXPECT_EQ(
      test::messageOf([&] { readGmshPostViews(folder.file("big.opt")); }),
      folder.file("big.opt") +
          ":2:20: error: View[0].TimeStep = 4294967296 is out of range: gmsh keeps it as an integer from "
          "-2147483648 to 2147483647");
  folder.write("low.opt", "View[0].NbIso = -1e10;\n");
  EXPECT_NE(test::messageOf([&] {
              readGmshPostViews(folder.file("low.opt"));
            }).find("View[0].NbIso = -1e10 is out"),
            std::string::npos);
  folder.write("fine.opt", "View[0].CustomMax = 1e300;\nView[0].TimeStep = 2147483647;\n");
  const std::vector<GmshPostView> views = readGmshPostViews(folder.file("fine.opt"));
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0].customMax, 1e300);
  EXPECT_EQ(views[0].timeStep, 2147483647);
}

// gmsh's way to show the stress on the deformed shape: the displacement view (VectorType 5) coloured
// by another view named by its ExternalView, that view itself hidden; a vector view left at gmsh's
// default VectorType (4, 3D arrows) is drawn as arrows; options lancer does not draw are named.
TEST(GmshPostOptions, ExternalViewsArrowsAndWhatIsNotApplied) {
  const test::ScratchFolder folder;
  folder.write("external.opt",
               "View[0].VectorType = 5;\nView[0].ExternalView = 1;\nView[0].Axes = 1; // Type of axes\n"
               "View[0].Max = 1.5; // Maximum value in the view (read-only)\nView[1].Visible = 0;\n"
               "View[2].Visible = 0;\n");
  SceneDescription description = oneMesh();
  const Mesh mesh = readMsh(description.meshes[0].file);
  applyGmshPostViews(description, mesh, readGmshPostViews(folder.file("external.opt")),
                     folder.file("external.opt"));
  const MeshInstance& coloured = description.meshes[0];
  ASSERT_TRUE(coloured.warp);
  EXPECT_EQ(coloured.warp->field, "displacement");
  ASSERT_TRUE(coloured.colorBy);
  EXPECT_EQ(coloured.colorBy->field, "stress");
  EXPECT_EQ(coloured.colorBy->component.kind, FieldComponent::Kind::VonMises);
  EXPECT_TRUE(coloured.annotations.empty());
  ASSERT_EQ(description.notes.size(), 1u);
  EXPECT_EQ(description.notes[0],
            folder.file("external.opt") + ": warning: lancer does not draw these gmsh options: View[0].Axes");

  folder.write("arrows.opt", "View[0].Visible = 1;\nView[1].Name = \"stress\";\nView[2].Visible = 0;\n");
  SceneDescription withArrows = oneMesh();
  applyGmshPostViews(withArrows, mesh, readGmshPostViews(folder.file("arrows.opt")),
                     folder.file("arrows.opt"));
  const MeshInstance& drawn = withArrows.meshes[0];
  EXPECT_FALSE(drawn.warp);
  ASSERT_EQ(drawn.annotations.size(), 1u);
  ASSERT_TRUE(std::holds_alternative<ArrowSpec>(drawn.annotations[0]));
  EXPECT_EQ(std::get<ArrowSpec>(drawn.annotations[0]).field, "displacement");
  ASSERT_TRUE(drawn.colorBy);
  EXPECT_EQ(drawn.colorBy->field, "stress");
  EXPECT_TRUE(withArrows.notes.empty());
}

}  // namespace
}  // namespace lancer
