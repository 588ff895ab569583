// Element-node data ($ElementNodeData) drawn as a user draws it, on gmsh-made fixtures
// (scripts/make_element_node_fixtures.py) where "g" holds f = x + 2y + 3z at every element's nodes
// and "f" the same as node data: colours and isolines of "g" must be the picture of "f" byte for
// byte (after the orientation of the skin turned faces), a field constant per element the picture of
// its $ElementData twin, and warps and arrows stand at the nodes.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/warp.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// A scene of `mesh` coloured by `field` over [0, 6], with isolines of it.
std::string sceneOf(const std::string& mesh, const std::string& field, const std::string& output) {
  return "[[mesh]]\nfile = \"" + test::dataFile("element_node/" + mesh) + "\"\ncolor_by = { field = \"" +
         field + "\", range = [0, 6] }\nisolines = { field = \"" + field +
         "\", values = [1, 2, 3, 4, 5] }\n[[light]]\nposition = [3, 4, 5]\n[render]\nwidth = 96\nheight = "
         "72\n" +
         "output = \"" + output + "\"\n";
}

void expectSamePicture(const std::string& mesh, const std::string& a, const std::string& b) {
  const test::ScratchFolder folder;
  for (const std::string& field : {a, b}) {
    folder.write(field + ".toml", sceneOf(mesh, field, folder.file(field + ".png")));
    const test::CommandResult run = test::runCli("render " + test::quoted(folder.file(field + ".toml")));
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  test::expectSameFile(folder.file(a + ".png"), folder.file(b + ".png"));
}

TEST(ElementNodeRender, ColoursAndIsolinesOfAContinuousFieldAreItsNodeDatasPicture) {
  expectSamePicture("tet_v41_bin.msh", "f", "g");
  expectSamePicture("tet_v22_ascii.msh", "f", "g");
  expectSamePicture("quad9_v41_bin.msh", "f", "g");
}

TEST(ElementNodeRender, AFieldConstantPerElementIsItsElementDatasPicture) {
  const test::ScratchFolder folder;
  const std::string mesh = test::dataFile("element_node/tet_v41_bin.msh");
  for (const std::string field : {"jump", "jumpe"}) {
    const test::CommandResult run =
        test::runCli("render " + test::quoted(mesh) + " --color-by " + field + " --width 96 --height 72 -o " +
                     test::quoted(folder.file(field + ".png")));
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  test::expectSameFile(folder.file("jump.png"), folder.file("jumpe.png"));
}

TEST(ElementNodeRender, WarpsMoveEachNodeByItsElementsValue) {
  const Mesh fields = readMsh(test::dataFile("element_node/tet_v41_ascii.msh"));
  Mesh warped = fields;
  warpMesh(warped, fields, WarpSettings{"u", 2.0, {}}, {});
  for (std::uint32_t v = 0; v < fields.positions.size(); ++v) {
    const Vec3d before = fields.worldPosition(v), after = warped.worldPosition(v);
    EXPECT_NEAR(after.x, before.x * 1.2, 1e-5) << v;
    EXPECT_NEAR(after.y, before.y * 1.4, 1e-5) << v;
    EXPECT_NEAR(after.z, before.z, 1e-5) << v;
  }
}

TEST(ElementNodeRender, ArrowsStandAtNodes) {
  const Mesh mesh = readMsh(test::dataFile("element_node/tet_v41_ascii.msh"));
  ArrowSpec spec;
  spec.field = "u";
  const Mesh arrows = arrowMesh(spec, mesh, {}, nullptr);
  EXPECT_GT(arrows.faceCount(), 0u);
  spec.field = "jumpe";
  EXPECT_THROW(arrowMesh(spec, mesh, {}, nullptr), InputError);
}

TEST(ElementNodeRender, InfoNamesElementNodeData) {
  const test::CommandResult run =
      test::runCli("info " + test::quoted(test::dataFile("getdp/magnet_v2_b.pos")));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(test::contains(run.output, "\"b\"                      element-node data, 3 components"))
      << run.output;
}

}  // namespace
}  // namespace lancer
