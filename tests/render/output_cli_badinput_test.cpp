// Bad output options and keys: an unknown tone curve, an exposure that is no number of stops, a bit
// depth other than 8 or 16 (or 16 for a format without it), a DPI or quality out of range, an unknown
// extension, --loop for a video, layers for a format that cannot hold them,
// and a render whose pixels came out non-finite: one line, exit code 2, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "lancer/render/renderer.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

using test::quoted;

const std::string kScene = test::dataFile("render/bracket_ortho.toml");

struct BadCase {
  std::string arguments;  // after `lancer`, with OUT for the scratch folder
  std::string message;    // the whole first line of stderr, with OUT
};

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(OutputCliBadInput, OptionsAreOneLineAndExitTwo) {
  const test::ScratchFolder folder;
  const std::string scene = quoted(kScene);
  const std::vector<BadCase> cases = {
      {"render " + scene + " --tonemap agx -o OUT/a.png",
       "--tonemap: error: unknown tone map 'agx': use none, filmic or aces"},
      {"render " + scene + " --exposure nan -o OUT/a.png",
       "--exposure: error: --exposure must be a number of stops between -20 and 20, found nan"},
      {"render " + scene + " --exposure inf -o OUT/a.png",
       "--exposure: error: --exposure must be a number of stops between -20 and 20, found inf"},
      {"render " + scene + " --exposure 40 -o OUT/a.png",
       "--exposure: error: --exposure must be a number of stops between -20 and 20, found 40"},
      {"render " + scene + " --bit-depth 12 -o OUT/a.png",
       "--bit-depth: error: --bit-depth must be 8 or 16, found 12"},
      {"render " + scene + " --bit-depth 16 -o OUT/a.bmp",
       "OUT/a.bmp: error: 16-bit samples are written to PNG only: give -o NAME.png, or leave --bit-depth at "
       "8"},
      {"render " + scene + " --aovs albedo -o OUT/a.png",
       "--aovs: error: OUT/a.png cannot hold albedo, normal or depth layers: write an .exr (-o NAME.exr)"},
      {"render " + scene + " --aovs albedo,motion -o OUT/a.exr",
       "--aovs: error: unknown layer 'motion': use albedo, normal and depth, separated by commas"},
      {"animate " + scene + " --frames 2 --bit-depth 16 -o OUT/t.gif",
       "--bit-depth: error: 16-bit samples are written to numbered PNG frames only (-o frame_%04d.png); GIF "
       "and "
       "animated PNG hold 8 bits"},
      {"render " + scene + " --dpi 0 -o OUT/a.png",
       "--dpi: error: 0 is not a resolution in dots per inch: give a number above 0 and at most 65535 (e.g. "
       "300 "
       "for print)"},
      {"render " + scene + " --dpi -72 -o OUT/a.jpg",
       "--dpi: error: -72 is not a resolution in dots per inch: give a number above 0 and at most 65535"},
      {"render " + scene + " --quality 0 -o OUT/a.jpg",
       "--quality: error: quality 0 is out of range: use 1 (smallest file) to 100 (best picture); 90 unless "
       "given"},
      {"render " + scene + " --quality 101 -o OUT/a.webp", "--quality: error: quality 101 is out of range"},
      {"render " + scene + " -o OUT/a.tif",
       "OUT/a.tif: error: unknown image format: '.tif'; the supported extensions are .png, .jpg, .jpeg, "
       ".webp, "
       ".bmp, .ppm, .gif, .exr"},
      {"animate " + scene + " --frames 2 --loop 1 -o OUT/t.mp4",
       "--loop: error: --loop applies to an animated .gif or .png; whether a video repeats is its player's "
       "choice"},
      {"render " + scene + " --shard 0/2 --denoise -o OUT/a.png",
       "--shard: error: a job-array part holds 8-bit rows: --denoise, --bit-depth 16 and .exr need a render "
       "without --shard"},
  };
  for (const BadCase& bad : cases) {
    const std::string arguments = replaceAll(bad.arguments, "OUT", folder.path().string());
    const test::CommandResult result = test::runCli(arguments + " -q");
    EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.output;
    const std::string expected = replaceAll(bad.message, "OUT", folder.path().string());
    EXPECT_NE(result.output.find(expected), std::string::npos) << arguments << "\n" << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
  }
  const test::CommandResult both =
      test::runCli("render " + scene + " -q --linear --srgb -o " + quoted(folder.file("a.png")));
  EXPECT_EQ(both.exitCode, 2) << both.output;
  EXPECT_NE(both.output.find("--srgb excludes --linear"), std::string::npos) << both.output;
  EXPECT_TRUE(folder.entries().empty());
}

TEST(OutputCliBadInput, SceneKeys) {
  test::expectSceneErrorContains(
      "[render]\nencoding = \"gamma\"\n",
      "scene.toml:2:12: error: render.encoding must be \"srgb\" or \"linear\", found \"gamma\"");
  test::expectSceneErrorContains(
      "[render]\ntonemap = \"agx\"\n",
      "scene.toml:2:11: error: render.tonemap must be \"none\", \"filmic\" or \"aces\", found \"agx\"");
  test::expectSceneErrorContains("[render]\nexposure = nan\n", "render.exposure");
  test::expectSceneErrorContains("[render]\nexposure = 25.0\n", "render.exposure");
  test::expectSceneErrorContains("[render]\nbit_depth = 12\n",
                                 "scene.toml:2:13: error: render.bit_depth must be 8 or 16, found 12");
  test::expectSceneErrorContains(
      "[render]\nquality = 0\n",
      "scene.toml:2:11: error: quality 0 is out of range: use 1 (smallest file) to 100 (best picture)");
  test::expectSceneErrorContains("[render]\ndpi = 0\n",
                                 "scene.toml:2:7: error: 0 is not a resolution in dots per inch");
  test::expectSceneErrorContains("[render]\ndpi = -1.5\n",
                                 "scene.toml:2:7: error: -1.5 is not a resolution in dots per inch");
  test::expectSceneErrorContains("[render]\nsrgb = false\nencoding = \"linear\"\n",
                                 "render.encoding and render.srgb both say how the image is encoded");
}

TEST(OutputCliBadInput, NonFinitePixelsAreAnErrorNotAPicture) {
  // Three lights of 3e38 on one face: the sum overflows float to infinity.
  const test::ScratchFolder folder;
  const std::vector<char> bytes = test::readFileBytes(kScene);
  std::string scene(bytes.begin(), bytes.end());
  folder.copy(test::dataFile("render/bracket_coarse.msh"), "bracket_coarse.msh");
  folder.copy(test::dataFile("render/floor.msh"), "floor.msh");
  const std::string light = "\n[[light]]\nposition = [-4, 8, 5]\nintensity = [3e38, 3e38, 3e38]\n";
  scene += light + light + light;
  folder.write("hot.toml", scene);
  const test::CommandResult result =
      test::runCli("render -q " + quoted(folder.file("hot.toml")) + " -o " + quoted(folder.file("hot.png")));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find(folder.file("hot.toml") + ": error: pixel "), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("came out non-finite"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("so no image was written"), std::string::npos) << result.output;
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"bracket_coarse.msh", "floor.msh", "hot.toml"}));
}

// Every integrator goes through the one pixel loop and its one check: the same message, exit code 2.
TEST(OutputCliBadInput, NonFinitePixelsAreTheSameErrorForEveryIntegrator) {
  const test::ScratchFolder folder;
  const std::vector<char> bytes = test::readFileBytes(kScene);
  std::string scene(bytes.begin(), bytes.end());
  folder.copy(test::dataFile("render/bracket_coarse.msh"), "bracket_coarse.msh");
  folder.copy(test::dataFile("render/floor.msh"), "floor.msh");
  // A background of 3e38 is a float, but four samples of it add up to infinity (the AO integrator
  // shows the background where nothing occludes; the others where the rays miss).
  folder.write("hot.toml", replaceAll(scene, "background = [1, 1, 1]", "background = [3e38, 3e38, 3e38]"));
  const std::string expected = folder.file("hot.toml") +
                               ": error: pixel 0,0 came out non-finite (rgb inf inf inf), so no image was "
                               "written: look for extreme light intensities or material values, and trace "
                               "the pixel with --pixel 0,0\n";
  for (const char* integrator : {"whitted", "path", "ao"}) {
    const test::CommandResult result =
        test::runCli("render -q " + quoted(folder.file("hot.toml")) + " --integrator " + integrator +
                     " --samples 4 --width 16 --height 12 -o " + quoted(folder.file("hot.png")));
    EXPECT_EQ(result.exitCode, 2) << integrator << ": " << result.output;
    EXPECT_EQ(result.output.substr(result.output.find(folder.file("hot.toml") + ": error:")), expected)
        << integrator;
  }
  // Path tracing under three lights of 3e38, as the Whitted test above.
  const std::string light = "\n[[light]]\nposition = [-4, 8, 5]\nintensity = [3e38, 3e38, 3e38]\n";
  folder.write("lights.toml", scene + light + light + light);
  const test::CommandResult path = test::runCli("render -q " + quoted(folder.file("lights.toml")) +
                                                " --integrator path --samples 4 --width 32 --height 24 -o " +
                                                quoted(folder.file("hot.png")));
  EXPECT_EQ(path.exitCode, 2) << path.output;
  EXPECT_NE(path.output.find("came out non-finite (rgb "), std::string::npos) << path.output;
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"bracket_coarse.msh", "floor.msh", "hot.toml", "lights.toml"}));
}

TEST(OutputCliBadInput, TheRendererThrowsForANonFinitePixel) {
  SceneDescription description = test::flatLitOnBlue(test::topDownView(8, 8, 4.0), {0.0, 0.0, 3.0});
  description.materials = {test::matteMaterial("grey", {0.2f, 0.2f, 0.2f}, {0.7f, 0.7f, 0.7f})};
  description.lights[0].intensity = {std::numeric_limits<float>::infinity(), 0, 0};
  description.meshes.resize(1);
  std::vector<Mesh> meshes;
  meshes.push_back(test::squareMesh(-1, -1, 1, 1, 0));
  const Scene scene = test::sceneFromMeshes(description, std::move(meshes));
  try {
    test::renderScene(description, scene);
    FAIL() << "no error";
  } catch (const NonFiniteRenderError& e) {
    EXPECT_EQ(e.x, 2);  // the square covers the middle half of the 8x8 view
    EXPECT_EQ(e.y, 2);
    EXPECT_NE(std::string(e.what()).find("pixel 2,2 came out non-finite (rgb inf"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lancer
