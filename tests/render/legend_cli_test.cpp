// `lancer render --legend FILE`: writes the colour bar of the first field-coloured mesh beside the
// picture (with --shard, the first task writes it), and refuses (exit 2, nothing written) when no mesh is
// coloured, when the legend cannot be written or drawn (its folder, the font: found before the render,
// the picture untouched) and when it is the picture's own path. The legend is published with the
// picture: a render that fails on the way leaves neither, nor a hidden file.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "lancer/image/image_io.hpp"
#include "lancer/image/legend.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::quoted;

// `lancer render SCENE -q --linear -o a.png --legend legend.png` with both outputs in `folder` (linear:
// the legend sheet compared value for value).
test::CommandResult renderWithLegend(const std::string& scene, const test::ScratchFolder& folder) {
  return test::runCli("render " + quoted(test::dataFile("render/" + scene)) + " -q --linear -o " +
                      quoted(folder.file("a.png")) + " --legend " + quoted(folder.file("legend.png")));
}

TEST(LegendCli, WritesTheColourBarOfTheColouredMesh) {
  const test::ScratchFolder folder;
  const test::CommandResult result = renderWithLegend("field_square.toml", folder);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const Image legend = readPng(folder.file("legend.png"));
  // field_square.toml colours "temperature" with magma over [0.5, 3]: the sheet legendSheet draws.
  const LegendSpec spec{ColorMapKind::Magma, 0.5, 3, "temperature", "", 0};
  const Image expected = legendSheet({&spec, 1}, 300, 14, false);
  ASSERT_EQ(legend.width(), expected.width());
  ASSERT_EQ(legend.height(), expected.height());
  // The written file is dithered to 8 bits: within one step of the exact values.
  const auto written = encodeImage8(legend, TransferCurve::Linear, 3);
  const auto exact = encodeImage8(expected, TransferCurve::Linear, 3);
  ASSERT_EQ(written.size(), exact.size());
  for (std::size_t i = 0; i < written.size(); ++i)
    ASSERT_LE(std::abs(int(written[i]) - int(exact[i])), 1) << i;
}

// A job array's tasks share the scene's ranges, so its legends: the first task writes them (the
// same bytes as a render in one piece), the others leave the file to it.
TEST(LegendCli, TheFirstTaskOfAJobArrayWritesTheLegend) {
  const test::ScratchFolder folder;
  ASSERT_EQ(renderWithLegend("field_square.toml", folder).exitCode, 0);
  for (const int task : {1, 0}) {
    const std::string legend = folder.file(fmt::format("legend_{}.png", task));
    const test::CommandResult result = test::runCli(
        "render " + quoted(test::dataFile("render/field_square.toml")) + " -q --linear -o " +
        quoted(folder.file("part.png")) + fmt::format(" --shard {}/2", task) + " --legend " + quoted(legend));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    if (task == 0)
      test::expectSameFile(legend, folder.file("legend.png"));
    else
      EXPECT_FALSE(std::filesystem::exists(legend));
  }
}

TEST(LegendCli, NeedsAColouredMesh) {
  const test::ScratchFolder folder;
  const test::CommandResult result = renderWithLegend("bracket_ortho.toml", folder);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("--legend needs a mesh coloured by a field"), std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists(folder.file("a.png")));
  EXPECT_FALSE(std::filesystem::exists(folder.file("legend.png")));
}

// The picture a.png already holds "old image"; the command must fail with `message` and leave it.
void expectRefusedBeforeTheRender(const test::ScratchFolder& folder, const std::string& arguments,
                                  const std::string& message, const std::string& prefix = "") {
  folder.write("a.png", "old image");
  const test::CommandResult result =
      test::runCli("render " + quoted(test::dataFile("render/field_square.toml")) + " -q -o " +
                       quoted(folder.file("a.png")) + " " + arguments,
                   prefix);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find(message), std::string::npos) << result.output;
  EXPECT_EQ(folder.read("a.png"), "old image") << "the picture was replaced by a command that failed";
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.png"});
}

// The legend sheet is written before the render under a hidden name and renamed into place with the
// picture: a render that fails while tracing (its pixels overflow a float) leaves the old files as
// they were and no hidden file.
TEST(LegendCli, AFailedRenderPublishesNoLegend) {
  const test::ScratchFolder folder;
  std::ifstream in(test::dataFile("render/field_square.toml"));
  std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string white = "background = [1, 1, 1]", mesh = "\"../fields/node_xy_v22_ascii.msh\"";
  scene.replace(scene.find(white), white.size(), "background = [3e38, 3e38, 3e38]\nsamples = 4");
  scene.replace(scene.find(mesh), mesh.size(), "\"" + test::dataFile("fields/node_xy_v22_ascii.msh") + "\"");
  folder.write("scene.toml", scene);
  folder.write("a.png", "old image");
  folder.write("leg.png", "old legend");
  const test::CommandResult result =
      test::runCli("render " + quoted(folder.file("scene.toml")) + " -q -o " + quoted(folder.file("a.png")) +
                   " --legend " + quoted(folder.file("leg.png")));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("non-finite"), std::string::npos) << result.output;
  EXPECT_EQ(folder.read("a.png"), "old image");
  EXPECT_EQ(folder.read("leg.png"), "old legend");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"a.png", "leg.png", "scene.toml"}));
}

// Both outputs are written before either is published: a legend that cannot be written (here it
// exceeds the file size limit the picture fits under) fails the command before the picture is
// replaced, and the message names the legend.
TEST(LegendCli, ALegendThatCannotBeWrittenLeavesThePicture) {
  const test::ScratchFolder folder;
  folder.write("a.png", "old image");
  const test::CommandResult result =
      test::runCli("render " + quoted(test::dataFile("render/field_square.toml")) + " -q -o " +
                       quoted(folder.file("a.png")) + " --legend " + quoted(folder.file("leg.png")),
                   "trap '' XFSZ; ulimit -f 4;");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find(folder.file("leg.png") + ": error: writing failed"), std::string::npos)
      << result.output;
  EXPECT_EQ(folder.read("a.png"), "old image") << "the picture was replaced by a command that failed";
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.png"});
}

TEST(LegendCli, AFolderThatDoesNotExistIsFoundBeforeTheRender) {
  const test::ScratchFolder folder;
  expectRefusedBeforeTheRender(
      folder, "--legend " + quoted(folder.file("nofolder/leg.png")),
      "leg.png: error: cannot write here: the folder '" + folder.file("nofolder") + "' does not exist");
}

TEST(LegendCli, AFontThatCannotBeLoadedIsFoundBeforeTheRender) {
  const test::ScratchFolder folder;
  expectRefusedBeforeTheRender(folder, "--legend " + quoted(folder.file("leg.png")),
                               "/nonexistent/font.ttf: error: the font file does not exist",
                               "LANCER_FONT=/nonexistent/font.ttf");
}

TEST(LegendCli, TheLegendCannotBeThePicture) {
  const test::ScratchFolder folder;
  expectRefusedBeforeTheRender(
      folder, "--legend " + quoted(folder.path().string() + "/./a.png"),
      "--legend: error: '" + folder.path().string() +
          "/./a.png' is also the picture's output: give the legend a name of its own");
}

}  // namespace
}  // namespace lancer
