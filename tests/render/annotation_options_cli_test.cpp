// The command line reaches what needed a scene file: --log, --range, --legend, --isolines, --bands,
// --arrows and --clip on the quick look give the picture a scene file with the same keys gives, the
// values are checked where the scene file's are (exit 2, a message naming the option, no picture),
// and --help lists the options in groups.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "lancer/image/image_io.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

using test::quoted;

const std::string kMagnet = test::dataFile("getdp/magnet_v2_az.pos");
constexpr const char* kSize = " --width 240 --height 160 -q";

// `lancer render ARGUMENTS -o FOLDER/NAME`, which must succeed; the picture written.
Image rendered(const test::ScratchFolder& folder, const std::string& arguments, const std::string& name) {
  const std::string out = folder.file(name);
  const test::CommandResult run = test::runCli("render " + arguments + " -o " + quoted(out) + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return readPng(out);
}

// The scene file that says what the options say, on the quick look's background (its lights do not
// light a flat model's field colours, and a scene without lights does not either).
std::string sceneWith(const std::string& mesh, const std::string& meshKeys, const std::string& extra = "") {
  return "[render]\nbackground = [0.96, 0.96, 0.97]\n" + extra + "\n[[mesh]]\nfile = " + quoted(mesh) + "\n" +
         meshKeys + "\n";
}

TEST(AnnotationOptionsCli, RangeLegendIsolinesBandsAndClipAreTheSceneKeys) {
  const test::ScratchFolder folder;
  const Image options =
      rendered(folder,
               quoted(kMagnet) + kSize +
                   " --color-by az --range -0.002:0.02 --legend right --isolines 6 --bands 8 "
                   "--clip x=0.1 --clip 0,0.2,0,0,1,0",
               "options.png");
  folder.write(
      "scene.toml",
      sceneWith(kMagnet,
                "color_by = { field = \"az\", range = [-0.002, 0.02], legend = \"right\", bands = 8 }\n"
                "isolines = { field = \"az\", count = 6 }",
                "[[clip]]\npoint = [0.1, 0, 0]\nnormal = [1, 0, 0]\n"
                "[[clip]]\npoint = [0, 0.2, 0]\nnormal = [0, 1, 0]\n"));
  const Image scene = rendered(folder, quoted(folder.file("scene.toml")) + kSize, "scene.png");
  EXPECT_EQ(test::differingPixels(options, scene), 0);
  // And something was drawn: the clip planes removed x > 0.1, the legend sits at the right edge.
  const Image plain = rendered(folder, quoted(kMagnet) + kSize + " --color-by az", "plain.png");
  EXPECT_GT(test::differingPixels(options, plain), 5000);
}

TEST(AnnotationOptionsCli, ArrowsStandOnTheModel) {
  const std::string vectors = test::dataFile("fields/node_vector_v41_bin.msh");
  const test::ScratchFolder folder;
  const Image arrows = rendered(
      folder, quoted(vectors) + kSize + " --color-by temperature --arrows temperature", "arrows.png");
  const Image plain = rendered(folder, quoted(vectors) + kSize + " --color-by temperature", "plain.png");
  EXPECT_GT(test::differingPixels(arrows, plain), 500);
}

TEST(AnnotationOptionsCli, ArrowsAloneTakeTheLegendAndTheMap) {
  // The mesh is not coloured: --legend and --color-map go to its arrows (they were refused).
  const std::string vectors = test::dataFile("fields/node_vector_v41_bin.msh");
  const test::ScratchFolder folder;
  const Image legend =
      rendered(folder, quoted(vectors) + kSize + " --arrows temperature --legend right --color-map plasma",
               "legend.png");
  const Image plain = rendered(folder, quoted(vectors) + kSize + " --arrows temperature", "plain.png");
  EXPECT_GT(test::differingPixels(legend, plain), 500);
}

TEST(AnnotationOptionsCli, ArrowsAloneTakeTheLogScaleOrSayWhyNot) {
  // Grid arrows' magnitudes reach 0 where the field vanishes: --log alone is refused as the mesh's
  // colours refuse it (it was dropped for a linear legend), and with a range it is drawn.
  const std::string capacitor = test::dataFile("volume/capacitor.msh");
  const test::ScratchFolder folder;
  const std::string arrows = quoted(capacitor) + kSize + " --arrows e --arrow-grid 6,6,5 --legend right";
  const test::CommandResult refused =
      test::runCli("render " + arrows + " --log -o " + quoted(folder.file("refused.png")) + " 2>&1");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_TRUE(test::contains(refused.output, "--log: error: arrows of \"e\"")) << refused.output;
  EXPECT_TRUE(test::contains(refused.output, "e.g. --range ")) << refused.output;
  EXPECT_FALSE(std::filesystem::exists(folder.file("refused.png")));
  const Image log = rendered(folder, arrows + " --log --range 0.1:8", "log.png");
  const Image linear = rendered(folder, arrows + " --range 0.1:8", "linear.png");
  EXPECT_GT(test::differingPixels(log, linear), 300);
}

TEST(AnnotationOptionsCli, LogIsTheSceneKey) {
  const std::string square = test::dataFile("fields/node_xy_v41_bin.msh");
  const test::ScratchFolder folder;
  const Image options =
      rendered(folder, quoted(square) + kSize + " --color-by temperature --log --range 0.03:3 --isolines 3",
               "log.png");
  folder.write("scene.toml",
               sceneWith(square,
                         "color_by = { field = \"temperature\", scale = \"log\", range = [0.03, 3] }\n"
                         "isolines = { field = \"temperature\", count = 3 }"));
  const Image scene = rendered(folder, quoted(folder.file("scene.toml")) + kSize, "scene.png");
  EXPECT_EQ(test::differingPixels(options, scene), 0);
  const Image linear = rendered(
      folder, quoted(square) + kSize + " --color-by temperature --range 0.03:3 --isolines 3", "lin.png");
  EXPECT_GT(test::differingPixels(options, linear), 1000);
}

TEST(AnnotationOptionsCli, IsolinesOfElementDataComeWithANote) {
  const test::ScratchFolder folder;
  const std::string grid = test::dataFile("fields/element_centroids_grid_v41_ascii.msh");
  const test::CommandResult run =
      test::runCli("render " + quoted(grid) + " --width 64 --height 64 --color-by f --isolines 5 -o " +
                   quoted(folder.file("iso.png")) + " 2>&1");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(
      run.output.find("--isolines: warning: isolines of element data \"f\" follow its mean at each vertex"),
      std::string::npos)
      << run.output;
}

TEST(AnnotationOptionsCli, LitPathTracedIsolinesDarkenTheSurface) {
  // Black lines under --look studio: the paint is the albedo, so a line is darker than the surface
  // beside it whatever the light. The unit square with x + 2 y fills the picture straight on; the
  // middle of 3 lines over [0, 3], x + 2 y = 1.5, crosses the middle row at x = 0.5.
  const test::ScratchFolder folder;
  const Image image = rendered(folder,
                               quoted(test::dataFile("fields/node_xy_v41_bin.msh")) +
                                   " --look studio --samples 16 --width 96 --height 96 --isolines 3 "
                                   "--color-by temperature --linear -q",
                               "studio.png");
  float darkest = 3, brightest = 0;
  for (int i = 40; i <= 56; ++i) {
    const Rgba& p = image.at(i, 48);
    darkest = std::min(darkest, p.r + p.g + p.b);
    brightest = std::max(brightest, p.r + p.g + p.b);
  }
  EXPECT_LT(darkest, 0.5f * brightest);
}

// `lancer render MAGNET --color-by az ARGUMENTS -o out.png` refused: exit 2, `message` said, nothing
// written.
void expectRefused(const std::string& arguments, const std::string& message) {
  const test::ScratchFolder folder;
  const test::CommandResult run = test::runCli("render " + quoted(kMagnet) + " --color-by az " + arguments +
                                               " -o " + quoted(folder.file("out.png")) + " 2>&1");
  EXPECT_EQ(run.exitCode, 2) << arguments << "\n" << run.output;
  EXPECT_NE(run.output.find(message), std::string::npos) << arguments << "\n" << run.output;
  EXPECT_TRUE(folder.entries().empty()) << arguments;
}

TEST(AnnotationOptionsCliBadInput, EachValueIsCheckedWithTheOptionsName) {
  expectRefused("--range 1:0", "--range: error: --range must have min < max, found [1, 0]");
  expectRefused("--range 1", "--range: error: '1' is not MIN:MAX");
  expectRefused("--range a:b", "--range: error: 'a:b' is not MIN:MAX");
  expectRefused("--legend left",
                "--legend: error: 'left' is not a place for the legend: use right, bottom or none");
  expectRefused("--bands 0", "--bands: error: --bands 0 is not a number of colour bands from 1 to 256");
  expectRefused("--isolines 1001",
                "--isolines: error: --isolines 1001 is not a number of isolines from 1 to 1000");
  expectRefused("--clip x=y", "--clip: error: 'x=y' is not a cutting plane: use AXIS=VALUE");
  expectRefused("--clip 1,2,3", "--clip: error: '1,2,3' is not a cutting plane");
  expectRefused("--clip 0,0,0,0,0,0",
                "--clip: error: a cutting plane needs a finite point and a normal other");
  expectRefused("--arrows nothing", "--arrows: error: arrows field \"nothing\" is not in");
  // --log as scale = "log": the field az reaches 0 and below, the range must start above 0.
  expectRefused("--log", "--log: error: color_by field \"az\" in ");
  expectRefused("--log", "but --log needs values > 0: give a range whose low end is > 0, e.g. --range ");
  expectRefused("--log", "or leave --log out");
  expectRefused("--log --range 0:0.02", "--range: error: --range must have min > 0 with scale = \"log\"");
}

TEST(AnnotationOptionsCliBadInput, AFieldsAnnotationNeedsAColouredMesh) {
  const test::ScratchFolder folder;
  for (const char* option : {"--isolines 4", "--bands 4", "--range 0:1", "--legend right", "--log"}) {
    const test::CommandResult run = test::runCli("render " + quoted(kMagnet) + " " + option + " -o " +
                                                 quoted(folder.file("out.png")) + " 2>&1");
    EXPECT_EQ(run.exitCode, 2) << option;
    EXPECT_NE(run.output.find("goes with a field's colours, and no mesh is coloured: add --color-by FIELD"),
              std::string::npos)
        << run.output;
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AnnotationOptionsCli, LegendFileKeepsItsOlderSpelling) {
  const test::ScratchFolder folder;
  rendered(folder, quoted(kMagnet) + kSize + " --color-by az --legend-file " + quoted(folder.file("a.png")),
           "p.png");
  rendered(folder, quoted(kMagnet) + kSize + " --color-by az --legend " + quoted(folder.file("b.png")),
           "q.png");
  test::expectSameFile(folder.file("a.png"), folder.file("b.png"));
}

TEST(AnnotationOptionsCli, HelpListsTheOptionsInGroups) {
  for (const char* command : {"render", "animate"}) {
    const test::CommandResult help = test::runCli(std::string(command) + " --help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    std::size_t last = 0;
    for (const char* group : {"Camera:", "Look:", "Results:", "Output:", "Quality:", "Cluster:"}) {
      const std::size_t at = help.output.find(std::string("\n") + group);
      ASSERT_NE(at, std::string::npos) << command << " " << group << "\n" << help.output;
      EXPECT_GT(at, last) << command << " " << group;
      last = at;
    }
    for (const char* option :
         {"--range", "--legend", "--isolines", "--bands", "--arrows", "--clip", "--shading"})
      EXPECT_NE(help.output.find(option), std::string::npos) << command << " " << option;
  }
}

}  // namespace
}  // namespace lancer
