// A view set up in gmsh's GUI and saved with its options (tests/data/results/cantilever.msh.opt,
// written by gmsh through scripts/make_result_fixtures.py): the displacement view drawn as the
// deformed shape, the stress at its time step on the custom range, the hidden view left out.
#include "lancer/scene/gmsh_post_options.hpp"

#include <gtest/gtest.h>

#include "lancer/mesh/msh_reader.hpp"
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
  EXPECT_EQ(mesh.colorBy->gmshIntervalsType, 1);
  EXPECT_EQ(mesh.colorBy->gmshNbIso, 8);
  EXPECT_EQ(description.when.step, 2);
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

}  // namespace
}  // namespace lancer
