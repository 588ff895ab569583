// `lancer animate` through the built CLI on the committed 4-frame turntable: the GIF decoded by
// giflib (and Pillow / ImageMagick when installed) against the true-colour frames, the animated PNG,
// numbered frames bit-identical to `lancer render` at each angle, and Ctrl-C leaving outputs alone.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lancer/image/image_io.hpp"
#include "lancer/render/animation.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/gif_decoder.hpp"
#include "support/golden.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

using test::quoted;
using test::runCli;
using test::ScratchFolder;

// Renders the turntable's frames as numbered PNGs (the true-colour reference) into `folder`.
std::vector<std::vector<std::uint8_t>> trueColourFrames(const ScratchFolder& folder) {
  const test::CommandResult result =
      runCli("animate -q " + quoted(test::kTurntableScene) + " -o " + quoted(folder.file("f_%04d.png")));
  EXPECT_EQ(result.exitCode, 0) << result.output;
  std::vector<std::vector<std::uint8_t>> frames;
  for (int k = 0; k < 4; ++k) frames.push_back(test::pngRgb8(folder.file(fmt::format("f_{:04d}.png", k))));
  return frames;
}

// Each frame of `gif` close to the same frame of `truth`, as close as a dithered 256-colour palette gets.
void expectCloseToTheTrueColourFrames(const test::DecodedGif& gif,
                                      const std::vector<std::vector<std::uint8_t>>& truth) {
  ASSERT_EQ(gif.frames.size(), truth.size());
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const test::SampleError error = test::sampleError(gif.frames[k].canvas, truth[k]);
    EXPECT_LT(error.mean, 3.0) << "frame " << k;
    EXPECT_LE(error.max, 40) << "frame " << k;
  }
}

TEST(AnimateCli, GifHasTheFramesSizeDelayAndLoopCountAndIsCloseToTheTrueColourFrames) {
  ScratchFolder folder;
  const auto truth = trueColourFrames(folder);
  const test::CommandResult result =
      runCli("animate " + quoted(test::kTurntableScene) + " --loop 3 -o " + quoted(folder.file("t.gif")));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // The scene asks for 12 fps; 100/12 hundredths rounds to 8, and the command says so.
  test::expectContainsAll(result.output, {"12 fps plays at 12.5 fps (a delay of 8/100 s)", "4 frames 64x48"});

  const test::DecodedGif gif = test::decodeGif(folder.file("t.gif"));
  ASSERT_NO_FATAL_FAILURE(
      test::expectGifLayout(gif, {.width = 64, .height = 48, .loopCount = 3, .frames = 4, .delay = 8}));
  expectCloseToTheTrueColourFrames(gif, truth);  // ordered dither over a 256-colour palette
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"f_0000.png", "f_0001.png", "f_0002.png", "f_0003.png", "t.gif"}));
}

TEST(AnimateCli, PerFramePalettesErrorDiffusionAndPlayOnce) {
  ScratchFolder folder;
  const auto truth = trueColourFrames(folder);
  for (const char* dither : {"floyd-steinberg", "none"}) {
    SCOPED_TRACE(dither);
    const test::CommandResult result = runCli("animate -q " + quoted(test::kTurntableScene) +
                                              " --fps 25 --loop -1 --palette per-frame --dither " + dither +
                                              " -o " + quoted(folder.file("t.gif")));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output, "");  // 25 fps is exact: nothing to say, and -q
    const test::DecodedGif gif = test::decodeGif(folder.file("t.gif"));
    ASSERT_NO_FATAL_FAILURE(test::expectGifLayout(gif, {.width = 64,
                                                        .height = 48,
                                                        .globalPalette = false,
                                                        .loopCount = std::nullopt,
                                                        .frames = 4,
                                                        .delay = 4}));
    expectCloseToTheTrueColourFrames(gif, truth);
  }
}

std::string writeScript(const ScratchFolder& folder, const std::string& text) {
  const std::string path = folder.file("check.py");
  std::ofstream(path) << text;
  return path;
}

// Pillow decodes GIF and APNG on its own; per frame it prints the duration in ms and the mean absolute
// difference (0..255, over R, G, B) from the numbered true-colour frame.
constexpr const char* kPillowCheck = R"(import sys
from PIL import Image, ImageSequence, ImageChops, ImageStat
im = Image.open(sys.argv[1])
print(im.format, im.size[0], im.size[1], im.n_frames, im.info.get('loop'))
for k, f in enumerate(ImageSequence.Iterator(im)):
    truth = Image.open(sys.argv[2] % k).convert('RGB')
    diff = ImageStat.Stat(ImageChops.difference(f.convert('RGB'), truth)).mean
    print(round(f.info.get('duration')), '%.2f' % (sum(diff) / 3))
)";

TEST(AnimateCliIndependentDecoders, PillowReadsTheGifAndTheAnimatedPng) {
  const std::optional<std::string> python = test::pythonWithPillow();
  if (!python) GTEST_SKIP() << "no python3 with PIL (Debian: python3-pil)";
  ScratchFolder folder;
  trueColourFrames(folder);
  ASSERT_EQ(
      runCli("animate -q " + quoted(test::kTurntableScene) + " --loop 2 -o " + quoted(folder.file("t.gif")))
          .exitCode,
      0);
  ASSERT_EQ(
      runCli("animate -q " + quoted(test::kTurntableScene) + " -o " + quoted(folder.file("t.png"))).exitCode,
      0);
  const std::string script = writeScript(folder, kPillowCheck);
  const test::CommandResult gif =
      test::runShell(*python + " " + quoted(script) + " " + quoted(folder.file("t.gif")) + " " +
                     quoted(folder.file("f_%04d.png")) + " 2>&1");
  ASSERT_EQ(gif.exitCode, 0) << gif.output;
  std::istringstream lines(gif.output);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "GIF 64 48 4 2");
  for (int k = 0; k < 4; ++k) {
    std::getline(lines, line);
    int duration = 0;
    double difference = 99;
    std::istringstream(line) >> duration >> difference;
    EXPECT_EQ(duration, 80) << line;
    EXPECT_LT(difference, 3.0) << line;
  }
  // The animated PNG is lossless: every frame equals the numbered PNG exactly; 1/12 s is 83.3 ms.
  const test::CommandResult apng =
      test::runShell(*python + " " + quoted(script) + " " + quoted(folder.file("t.png")) + " " +
                     quoted(folder.file("f_%04d.png")) + " 2>&1");
  ASSERT_EQ(apng.exitCode, 0) << apng.output;
  EXPECT_EQ(apng.output, "PNG 64 48 4 0\n83 0.00\n83 0.00\n83 0.00\n83 0.00\n");
}

TEST(AnimateCliIndependentDecoders, ImageMagickReadsTheGif) {
  if (!test::imageMagickInstalled()) GTEST_SKIP() << "ImageMagick not installed";
  ScratchFolder folder;
  const auto truth = trueColourFrames(folder);
  ASSERT_EQ(
      runCli("animate -q " + quoted(test::kTurntableScene) + " -o " + quoted(folder.file("t.gif"))).exitCode,
      0);
  const test::CommandResult identify =
      test::runShell("identify -format '%W %H %T %n|' " + quoted(folder.file("t.gif")) + " 2>&1");
  EXPECT_EQ(identify.output, "64 48 8 4|64 48 8 4|64 48 8 4|64 48 8 4|");  // canvas, delay, frame count
  const test::CommandResult iterations = test::runShell(
      "identify -verbose " + quoted(folder.file("t.gif") + "[0]") + " | grep -m1 'Iterations:' 2>&1");
  EXPECT_EQ(iterations.output, "  Iterations: 0\n");  // 0 = forever, the default
  const std::string raw = folder.file("frames.rgb");
  ASSERT_EQ(
      std::system(("convert " + quoted(folder.file("t.gif")) + " -coalesce rgb:" + quoted(raw)).c_str()), 0);
  const std::vector<std::uint8_t> decoded = test::readBytes(raw);
  ASSERT_EQ(decoded.size(), 4u * 64 * 48 * 3);
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t size = truth[k].size();
    const std::vector<std::uint8_t> frame(decoded.begin() + static_cast<std::ptrdiff_t>(k * size),
                                          decoded.begin() + static_cast<std::ptrdiff_t>((k + 1) * size));
    EXPECT_LT(test::sampleError(frame, truth[k]).mean, 3.0) << "frame " << k;
  }
}

// Walks the PNG chunks: names in order, with CRCs checked, and the raw data of each.
struct PngChunk {
  std::string type;
  std::vector<std::uint8_t> data;
};

std::uint32_t u32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

std::vector<PngChunk> pngChunks(const std::vector<std::uint8_t>& file) {
  std::vector<PngChunk> chunks;
  std::size_t at = 8;
  while (at + 12 <= file.size()) {
    const std::uint32_t length = u32(&file[at]);
    if (at + 12 + length > file.size()) break;
    PngChunk chunk{std::string(file.begin() + static_cast<std::ptrdiff_t>(at + 4),
                               file.begin() + static_cast<std::ptrdiff_t>(at + 8)),
                   std::vector<std::uint8_t>(file.begin() + static_cast<std::ptrdiff_t>(at + 8),
                                             file.begin() + static_cast<std::ptrdiff_t>(at + 8 + length))};
    const uLong crc = crc32(0L, &file[at + 4], length + 4);
    EXPECT_EQ(crc, u32(&file[at + 8 + length])) << "CRC of " << chunk.type;
    chunks.push_back(std::move(chunk));
    at += 12 + length;
  }
  EXPECT_EQ(at, file.size());
  return chunks;
}

TEST(AnimateCli, AnimatedPngHasOneControlChunkPerFrameAndFrameZeroAsItsDefaultImage) {
  ScratchFolder folder;
  const auto truth = trueColourFrames(folder);
  const test::CommandResult result = runCli("animate -q " + quoted(test::kTurntableScene) +
                                            " --fps 30 --loop 4 -o " + quoted(folder.file("t.png")));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // libpng (which knows nothing of APNG) reads the default image: frame 0, exactly.
  EXPECT_EQ(test::pngRgb8(folder.file("t.png")), truth[0]);
  std::string order;
  std::vector<std::uint32_t> sequence;
  for (const PngChunk& chunk : pngChunks(test::readBytes(folder.file("t.png")))) {
    order += chunk.type + " ";
    if (chunk.type == "acTL") {
      EXPECT_EQ(u32(&chunk.data[0]), 4u);  // frames
      EXPECT_EQ(u32(&chunk.data[4]), 5u);  // plays: --loop 4 repeats after the first showing
    }
    if (chunk.type == "fcTL") {
      EXPECT_EQ(u32(&chunk.data[4]), 64u);
      EXPECT_EQ(u32(&chunk.data[8]), 48u);
      EXPECT_EQ((chunk.data[20] << 8) | chunk.data[21], 1);   // delay numerator
      EXPECT_EQ((chunk.data[22] << 8) | chunk.data[23], 30);  // delay denominator: exactly 1/30 s
    }
    if (chunk.type == "fcTL" || chunk.type == "fdAT") sequence.push_back(u32(&chunk.data[0]));
  }
  // sRGB-encoded by default, so marked sRGB.
  EXPECT_EQ(order, "IHDR sRGB acTL fcTL IDAT fcTL fdAT fcTL fdAT fcTL fdAT IEND ");
  EXPECT_EQ(sequence, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6}));
}

// The camera of frame k written into a scene file that `lancer render` reads back exactly (%.17g).
std::string sceneWithCamera(const std::string& base, const CameraSettings& camera) {
  auto triple = [](const Vec3d& v) { return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x, v.y, v.z); };
  std::string text = base;
  const std::string oldCamera = "position = [4, 3.5, 5]\nlook_at = [0, 0.6, 0]\n";
  const std::size_t at = text.find(oldCamera);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, oldCamera.size(),
               fmt::format("position = {}\nlook_at = {}\nup = {}\n", triple(*camera.position),
                           triple(*camera.lookAt), triple(camera.up)));
  for (const char* mesh : {"bracket_coarse.msh", "floor.msh"}) {
    const std::string name = fmt::format("\"{}\"", mesh);
    text.replace(text.find(name), name.size(), fmt::format("\"{}/render/{}\"", LANCER_TEST_DATA_DIR, mesh));
  }
  return text;
}

TEST(AnimateCli, NumberedFramesAreBitIdenticalToRenderAtEachAngle) {
  ScratchFolder folder;
  const auto truth = trueColourFrames(folder);
  const SceneDescription description = loadScene(test::kTurntableScene);
  const Scene scene = buildScene(description);
  const std::string base = test::readText(test::kTurntableScene);
  for (int k = 0; k < 4; ++k) {
    const CameraSettings camera = orbitCamera(description.camera, *description.animation, scene,
                                              description.render.width, description.render.height, k);
    const std::string toml = folder.file(fmt::format("view_{}.toml", k));
    std::ofstream(toml) << sceneWithCamera(base, camera);
    const std::string still = folder.file(fmt::format("view_{}.png", k));
    const test::CommandResult result = runCli("render -q " + quoted(toml) + " -o " + quoted(still));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(test::readPictureBytes(still),
              test::readPictureBytes(folder.file(fmt::format("f_{:04d}.png", k))))
        << "frame " << k;
  }
  // Frame 0 is the scene's own view: plain `lancer render` of the same file.
  ASSERT_EQ(runCli("render -q " + quoted(test::kTurntableScene) + " -o " + quoted(folder.file("plain.png")))
                .exitCode,
            0);
  EXPECT_EQ(test::readPictureBytes(folder.file("plain.png")),
            test::readPictureBytes(folder.file("f_0000.png")));
  EXPECT_NE(truth[0], truth[1]);
}

// `--orbit light:0`: the camera stays, light 0 turns; frame k matches `lancer render` with the light
// put where the orbit takes it (within rounding: the light's position passes through scene space).
TEST(AnimateCli, LightOrbitFramesMatchRendersWithTheLightMoved) {
  ScratchFolder folder;
  const test::CommandResult result = runCli("animate -q " + quoted(test::kTurntableScene) +
                                            " --orbit light:0 -o " + quoted(folder.file("l_%d.png")));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string base = test::readText(test::kTurntableScene);
  const SceneDescription description = loadScene(test::kTurntableScene);
  const Image frame0 = readPng(folder.file("l_0.png"));
  for (int k = 0; k < 4; ++k) {
    const Vec3d light =
        rotateAbout({-4, 8, 5}, {0, 0, 0}, {0, 1, 0}, orbitAngleDegrees(*description.animation, k));
    std::string text = sceneWithCamera(base, description.camera);
    const std::string oldLight = "position = [-4, 8, 5]";
    text.replace(text.find(oldLight), oldLight.size(),
                 fmt::format("position = [{:.17g}, {:.17g}, {:.17g}]", light.x, light.y, light.z));
    const std::string toml = folder.file(fmt::format("light_{}.toml", k));
    std::ofstream(toml) << text;
    const std::string still = folder.file(fmt::format("light_{}.png", k));
    ASSERT_EQ(runCli("render -q " + quoted(toml) + " -o " + quoted(still)).exitCode, 0);
    const Image frame = readPng(folder.file(fmt::format("l_{}.png", k)));
    EXPECT_GT(test::psnr8(frame, readPng(still)), 40.0) << "frame " << k;
    if (k > 0) {
      EXPECT_LT(test::psnr8(frame, frame0), 30.0) << "frame " << k << ": the light moved";
    }
  }
}

// Ctrl-C (SIGINT from `timeout`) in the middle of a long animation: exit 130, the old files as they
// were, no temporary files left.
TEST(AnimateCli, InterruptLeavesExistingOutputUntouched) {
  ScratchFolder folder;
  const std::vector<std::uint8_t> old = {'o', 'l', 'd'};
  for (const char* name : {"t.gif", "t.png", "f_0000.png", "f_0001.png"})
    test::writeBytes(folder.file(name), old);
  for (const char* output : {"t.gif", "t.png", "f_%04d.png"}) {
    SCOPED_TRACE(output);
    const test::CommandResult result = runCli(
        "animate -q " + quoted(test::kTurntableScene) + " --frames 10000 -o " + quoted(folder.file(output)),
        "timeout -s INT --preserve-status 1.5");
    EXPECT_EQ(result.exitCode, 130) << result.output;
    EXPECT_TRUE(test::contains(result.output, "lancer: interrupted; ")) << result.output;
    for (const char* name : {"t.gif", "t.png", "f_0000.png", "f_0001.png"})
      EXPECT_EQ(test::readBytes(folder.file(name)), old) << name;
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"f_0000.png", "f_0001.png", "t.gif", "t.png"}));
  }
}

}  // namespace
}  // namespace lancer
