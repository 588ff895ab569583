// What users expect of the command line: --help in groups, did-you-mean for options, the named
// views and the orbit of the automatic camera, --background and --transparent, -o - (the PNG on
// stdout, nothing else there) and an output named after the input when -o is missing.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "lancer/image/image_io.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::contains;
using test::quoted;
using test::runCli;

const std::string kMesh = test::dataFile("render/bracket_coarse.msh");
const std::string kSmall = " --width 24 --height 18 -q ";

TEST(CommandLineCli, EveryRenderAndAnimateOptionIsInAGroup) {
  for (const char* command : {"render", "animate"}) {
    SCOPED_TRACE(command);
    const test::CommandResult help = runCli(std::string(command) + " --help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    // CLI11 lists the options of no group under "Options:": only --help is left there.
    std::istringstream lines(help.output);
    std::string line, section;
    int ungrouped = 0;
    while (std::getline(lines, line)) {
      if (!line.empty() && line[0] != ' ') section = line;
      if (section == "Options:" && line.rfind("  -", 0) == 0) {
        ++ungrouped;
        EXPECT_TRUE(contains(line, "-h,--help")) << line;
      }
    }
    EXPECT_EQ(ungrouped, 1);
    for (const char* group : {"Input:", "Camera:", "Look:", "Results:", "Output:", "Quality:", "Cluster:"})
      EXPECT_TRUE(contains(help.output, std::string("\n") + group + "\n")) << group;
    EXPECT_TRUE(contains(help.output, "--view TEXT:{iso,front,back,left,right,top,bottom}"));
  }
}

TEST(CommandLineCli, UnknownOptionsGetTheClosestName) {
  const test::ScratchFolder folder;
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"render " + quoted(kMesh) + " --widht 80",
       "lancer: error: unknown option '--widht' (did you mean '--width'?); lancer render --help lists the "
       "options\n"},
      {"render " + quoted(kMesh) + " --elevaton=30",
       "unknown option '--elevaton' (did you mean '--elevation'?)"},
      {"animate " + quoted(kMesh) + " --fram 3", "unknown option '--fram' (did you mean '--frames'?)"},
      {"render " + quoted(kMesh) + " --frobnicate",
       "lancer: error: unknown option '--frobnicate'; lancer render --help lists the options\n"},
      {"--verison", "lancer: error: unknown option '--verison' (did you mean '--version'?); lancer --help"},
      {"rendr " + quoted(kMesh), "unknown subcommand 'rendr' (did you mean 'render'?)"},
  };
  for (const auto& bad : cases) {
    const test::CommandResult result = runCli(bad.arguments);
    SCOPED_TRACE(bad.arguments);
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_TRUE(contains(result.output, bad.message)) << result.output;
  }
  // A negative number is a value, not an option.
  EXPECT_EQ(runCli("render " + quoted(kMesh) + kSmall + "--exposure -1 -o " + quoted(folder.file("a.png")))
                .exitCode,
            0);
}

// The PNG of `lancer render bracket_coarse.msh OPTIONS` (small, quiet), read back as 8-bit values.
Image renderPng(const test::ScratchFolder& folder, const std::string& options,
                PngDescription* header = nullptr) {
  const std::string out = folder.file("view.png");
  const test::CommandResult result =
      runCli("render " + quoted(kMesh) + kSmall + options + " -o " + quoted(out));
  EXPECT_EQ(result.exitCode, 0) << result.output;
  return readPng(out, TransferCurve::Linear, header);
}

bool samePixels(const Image& a, const Image& b) {
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (!(a.at(x, y) == b.at(x, y))) return false;
  return true;
}

TEST(CommandLineCli, ViewsAndOrbitTurnTheAutomaticCamera) {
  const test::ScratchFolder folder;
  const Image iso = renderPng(folder, "");
  EXPECT_TRUE(samePixels(renderPng(folder, "--view iso"), iso));  // the default view
  const Image front = renderPng(folder, "--view front");
  const Image top = renderPng(folder, "--view top");
  EXPECT_FALSE(samePixels(front, iso));
  EXPECT_FALSE(samePixels(front, top));
  // Raised by 90 degrees, the front view is the top view (to within a few edge pixels: the same frame
  // through other roundings).
  const Image raised = renderPng(folder, "--view front --elevation 90");
  int differ = 0;
  for (int y = 0; y < top.height(); ++y)
    for (int x = 0; x < top.width(); ++x) differ += std::abs(top.at(x, y).g - raised.at(x, y).g) > 2.5f / 255;
  EXPECT_LE(differ, 4);
  EXPECT_FALSE(samePixels(renderPng(folder, "--view front --azimuth 30"), front));
  EXPECT_FALSE(samePixels(renderPng(folder, "--zoom 2"), iso));
  EXPECT_TRUE(samePixels(renderPng(folder, "--zoom 1 --azimuth 0 --elevation 0"), iso));
}

TEST(CommandLineCli, BackgroundIsTheColourThePictureShows) {
  const test::ScratchFolder folder;
  for (const char* colour : {"'#ff8000'", "1,0.50196,0", "ORANGE"}) {
    SCOPED_TRACE(colour);
    const Image picture = renderPng(folder, std::string("--background ") + colour);
    const Rgba corner = picture.at(0, 0);
    EXPECT_EQ(encode8(corner.r), 255);
    EXPECT_EQ(encode8(corner.g), std::string(colour) == "ORANGE" ? 165 : 128);
    EXPECT_EQ(encode8(corner.b), 0);
  }
  PngDescription header;
  const Image transparent = renderPng(folder, "--transparent", &header);
  EXPECT_TRUE(header.alpha);
  EXPECT_EQ(transparent.at(0, 0).a, 0.0f);
  EXPECT_EQ(transparent.at(12, 9).a, 1.0f);  // the model, in the middle
}

TEST(CommandLineCli, DashOutputSendsThePngToStdoutAndNothingElse) {
  const test::ScratchFolder folder;
  const std::string mesh = quoted(kMesh);
  const test::CommandResult piped =
      test::runShell("TMPDIR=" + quoted(folder.path().string()) + " " + quoted(LANCER_CLI_PATH) + " render " +
                     mesh + " --width 24 --height 18 -o - > " + quoted(folder.file("piped.png")) + " 2> " +
                     quoted(folder.file("stderr.txt")));
  EXPECT_EQ(piped.exitCode, 0);
  ASSERT_EQ(runCli("render " + mesh + kSmall + "-o " + quoted(folder.file("file.png"))).exitCode, 0);
  test::expectSameFile(folder.file("piped.png"), folder.file("file.png"));
  EXPECT_TRUE(folder.read("stderr.txt").rfind("stdout: 24x18,", 0) == 0) << folder.read("stderr.txt");
  // The temporary file is gone.
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"file.png", "piped.png", "stderr.txt"}));
}

TEST(CommandLineCli, WithoutOutputThePictureIsNamedAfterTheInput) {
  const test::ScratchFolder folder;
  folder.copy(kMesh, "part.msh");
  const std::string here = "cd " + quoted(folder.path().string()) + " && " + quoted(LANCER_CLI_PATH);
  EXPECT_EQ(test::runShell(here + " render part.msh --width 16 --height 12 -q").exitCode, 0);
  EXPECT_EQ(test::runShell(here + " animate part.msh --frames 2 --width 16 --height 12 -q").exitCode, 0);
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"part.gif", "part.msh", "part.png"}));
}

TEST(CommandLineCli, BadViewsBackgroundsAndOutputsAreOneLine) {
  const test::ScratchFolder folder;
  const std::string mesh = quoted(kMesh);
  const std::string out = " -o " + quoted(folder.file("out.png"));
  const std::string scene = quoted(test::dataFile("render/bracket_ortho.toml"));
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"render " + mesh + " --view side" + out, "--view: side not in {iso,front,back,left,right,top,bottom}"},
      {"render " + mesh + " --elevation 95" + out,
       "--elevation: error: --elevation must be a number of degrees between -90 and 90, found 95"},
      {"render " + mesh + " --zoom 0" + out, "--zoom: error: --zoom must be a factor between 0.001 and 1000"},
      {"render " + scene + " --view top" + out,
       "--view: error: " + test::dataFile("render/bracket_ortho.toml") +
           " places its camera (camera.position): --view chooses the side of the automatic camera"},
      {"render " + mesh + " --gmsh-view --zoom 2" + out,
       "--zoom: error: --gmsh-view places the camera as gmsh"},
      {"render " + mesh + " --background navyy" + out,
       "--background: error: 'navyy' is not a colour (did you mean 'navy'?): use a CSS colour name (white, "
       "navy), #rrggbb, #rgb or r,g,b with each in 0..1"},
      {"render " + mesh + " --background 1,1" + out, "--background: error: '1,1' is not a colour"},
      {"render " + mesh + " --transparent -o " + quoted(folder.file("out.bmp")),
       "--transparent: error: " + folder.file("out.bmp") + " has no alpha channel"},
      {"render " + mesh + " --transparent --background white" + out, "--background excludes --transparent"},
      {"render " + mesh + " --progressive 1 --integrator path -o -",
       "-o: error: -o - sends one PNG to stdout: --progressive rewrites its file"},
      {"render " + mesh + " --width 0" + out, "--width: error: --width must be between 1 and 32768, found 0"},
      {"render " + mesh + " --threads 2000" + out,
       "--threads: error: --threads must be between 0 and 1024 (0: one per usable CPU), found 2000"},
  };
  for (const auto& bad : cases) {
    SCOPED_TRACE(bad.arguments);
    const test::CommandResult result = runCli(bad.arguments);
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_TRUE(contains(result.output, bad.message)) << result.output;
  }
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace lancer
