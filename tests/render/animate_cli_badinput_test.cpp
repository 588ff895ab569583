// `lancer animate` refuses bad options and bad [animation] keys with exit code 2 and a message that
// says what is wrong, before writing anything.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::contains;
using test::quoted;
using test::runCli;
using test::ScratchFolder;

struct BadCase {
  std::string options;
  std::string message;
};

TEST(AnimateCliBadInput, OptionsAreClearErrors) {
  ScratchFolder folder;
  const std::string out = folder.file("t.gif");
  const std::vector<BadCase> cases = {
      {"--orbit sun -o " + quoted(out),
       "--orbit: error: 'sun' is not an orbit: use 'camera' or 'light:K' with K from 0 to 1 (the scene has 2 "
       "lights)"},
      {"--orbit light:2 -o " + quoted(out), "'light:2' is not an orbit"},
      {"--orbit light:1x -o " + quoted(out), "'light:1x' is not an orbit"},
      {"--orbit light:+1 -o " + quoted(out), "'light:+1' is not an orbit"},
      {"--orbit 'light: 1' -o " + quoted(out), "'light: 1' is not an orbit"},
      {"--orbit light:99999999999 -o " + quoted(out), "'light:99999999999' is not an orbit"},
      {"--frames 0 -o " + quoted(out), "--frames: error: --frames must be between 1 and 10000, found 0"},
      {"--frames many -o " + quoted(out), "Could not convert: --frames = many"},
      {"-o -", "-o: error: animate writes a file (.gif, .png or numbered frames), not stdout"},
      {"--fps 0 -o " + quoted(out),
       "--fps: error: --fps must be a number of frames per second between 0.01 and 100, found 0"},
      {"--loop -2 -o " + quoted(out),
       "--loop: error: --loop must be between -1 and 65535 (0: forever, -1: play once), found -2"},
      {"--dither blue-noise -o " + quoted(out), "--dither: blue-noise not in {none,ordered,floyd-steinberg}"},
      {"--palette adaptive -o " + quoted(out), "--palette: adaptive not in {global,per-frame}"},
      {"--dither ordered -o " + quoted(folder.file("t.png")),
       "--dither: error: --dither applies to an animated .gif only"},
      {"--palette global -o " + quoted(folder.file("f_%04d.png")),
       "--palette: error: --palette applies to an animated .gif only"},
      {"--loop 2 -o " + quoted(folder.file("f_%04d.png")),
       "--loop: error: --loop applies to an animated .gif or .png, not to numbered frames"},
      {"-o " + quoted(folder.file("t.bmp")),
       "t.bmp: error: an animation is written as .gif, as an animated .png, as an .mp4 (H.264) or .webm "
       "(VP9) "
       "video, or as numbered frames with %04d"},
      {"-o " + quoted(folder.file("f_%x.png")),
       "a frame-sequence name needs one %d or %0Nd (e.g. frame_%04d.png)"},
      {"-o " + quoted(folder.file("f_%04d_%d.png")), "a frame-sequence name may hold only one %d"},
      {"-o " + quoted(folder.file("f_%04d.tiff")), "f_0000.tiff: error:"},
      {"-o " + quoted(folder.file("missing/t.gif")), "the folder"},
      {"-o " + quoted(folder.file("missing/f_%04d.png")), "the folder"},
      {"--frames 10000 --width 8000 --height 8000 -o " + quoted(out),
       "--palette: error: a global GIF palette keeps every frame until the end: 10000 frames of 8000x8000 "
       "need "
       "1788.1 GiB, more than half of this machine's"},
  };
  for (const BadCase& bad : cases) {
    SCOPED_TRACE(bad.options);
    const test::CommandResult result = runCli("animate " + quoted(test::kTurntableScene) + " " + bad.options);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_TRUE(contains(result.output, bad.message)) << result.output;
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AnimateCliBadInput, LightOrbitInASceneWithoutLights) {
  ScratchFolder folder;
  const std::string toml = folder.file("dark.toml");
  std::ofstream(toml) << fmt::format(
      "[render]\nwidth = 8\nheight = 6\n[[mesh]]\nfile = \"{}/render/floor.msh\"\n", LANCER_TEST_DATA_DIR);
  const test::CommandResult result =
      runCli("animate " + quoted(toml) + " --orbit light:0 -o " + quoted(folder.file("t.gif")));
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_TRUE(
      contains(result.output,
               "--orbit: error: 'light:0' is not an orbit here: the scene has no [[light]]; use 'camera'"))
      << result.output;
}

TEST(AnimateCliBadInput, BadAnimationKeysPointAtTheSceneFile) {
  ScratchFolder folder;
  std::string base = test::readText(test::kTurntableScene);
  for (const char* mesh : {"bracket_coarse.msh", "floor.msh"}) {
    const std::string name = fmt::format("\"{}\"", mesh);
    base.replace(base.find(name), name.size(), fmt::format("\"{}/render/{}\"", LANCER_TEST_DATA_DIR, mesh));
  }
  const std::size_t at = base.find("[animation]\n");
  ASSERT_NE(at, std::string::npos);
  const int line =
      static_cast<int>(std::count(base.begin(), base.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 2;
  const std::vector<BadCase> cases = {
      {"frames = 0\n",
       fmt::format("bad.toml:{}:10: error: animation.frames must be between 1 and 10000, found 0", line)},
      {"frames = 4\nfps = -1\n", fmt::format("bad.toml:{}:7: error: animation.fps must be a number of frames "
                                             "per second between 0.01 and 100, found -1",
                                             line + 1)},
      {"frames = 4\nspin = 2\n",
       fmt::format("bad.toml:{}:1: error: unknown key 'spin' in [animation]", line + 1)},
      {"frames = 4\norbit = \"light:5\"\n",
       fmt::format("bad.toml:{}:9: error: animation.orbit names light 5, but the scene has 2 lights",
                   line + 1)},
      {"frames = 4\naxis = [0, 0, 0]\n", "animation.axis must not be [0, 0, 0]"},
      {"frames = \"many\"\n", fmt::format("bad.toml:{}:", line)},
  };
  for (const BadCase& bad : cases) {
    SCOPED_TRACE(bad.options);
    std::string text = base;
    text.replace(at, std::string::npos, "[animation]\n" + bad.options);  // the whole section, to the end
    const std::string toml = folder.file("bad.toml");
    std::ofstream(toml) << text;
    const test::CommandResult result =
        runCli("animate " + quoted(toml) + " -o " + quoted(folder.file("t.gif")));
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_TRUE(contains(result.output, bad.message)) << result.output;
  }
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"bad.toml"});
}

}  // namespace
}  // namespace lancer
