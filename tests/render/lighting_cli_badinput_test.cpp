// The lighting options on the command line: --integrator, --noise, --look and --progressive (a finite
// number of seconds > 0), each bad value with its message (ours: exit code 2; CLI11 names the choices of a
// closed list), and a progressive render that ends with the image a plain render gives.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "lancer/image/exr_io.hpp"
#include "lancer/image/image_io.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

const std::string kMesh = LANCER_TEST_DATA_DIR "/render/bracket_coarse.msh";

// What two renders must agree on: a PNG's bytes less its text chunks (they record the command line),
// an EXR's pixels and layers as stored (its header records the command line too).
std::string bytesOf(const std::filesystem::path& path) {
  const auto raw = [](const auto& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(values[0]));
  };
  if (path.extension() != ".exr") return raw(test::readPictureBytes(path.string()));
  ExrLayers layers;
  const Image image = readExr(path.string(), &layers);
  std::vector<float> pixels;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgba p = image.at(x, y);
      pixels.insert(pixels.end(), {p.r, p.g, p.b, p.a});
    }
  return raw(pixels) + raw(layers.albedo) + raw(layers.normal) + raw(layers.depth);
}

TEST(LightingCli, NoiseOutsideZeroToOneIsAnInputError) {
  for (const char* noise : {"0", "1", "-0.5"}) {
    const test::CommandResult result = test::runCli(
        "render " + test::quoted(kMesh) + " -o /tmp/x.png --integrator path --noise " + noise + " 2>&1");
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_TRUE(test::contains(result.output, "--noise must be greater than 0 and less than 1"))
        << result.output;
  }
}

TEST(LightingCli, AdaptiveNoiseOutsideZeroToOneIsAnInputError) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "lancer_adaptive_noise_bad.png";
  std::filesystem::remove(out);
  for (const char* noise : {"0", "1", "-0.5", "nan", "1e300"}) {
    const test::CommandResult result =
        test::runCli("render " + test::quoted(kMesh) + " -o " + test::quoted(out.string()) +
                     " --integrator path --adaptive-noise " + noise + " 2>&1");
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_TRUE(test::contains(result.output,
                               "--adaptive-noise: error: --adaptive-noise must be greater than 0 "
                               "and less than 1"))
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << noise;
  }
}

TEST(LightingCli, UnknownIntegratorAndLookNameTheChoices) {
  test::CommandResult result =
      test::runCli("render " + test::quoted(kMesh) + " -o /tmp/x.png --integrator photon 2>&1");
  EXPECT_NE(result.exitCode, 0);
  EXPECT_TRUE(test::contains(result.output, "whitted")) << result.output;
  result = test::runCli("render " + test::quoted(kMesh) + " -o /tmp/x.png --look noir 2>&1");
  EXPECT_NE(result.exitCode, 0);
  EXPECT_TRUE(test::contains(result.output, "studio")) << result.output;
}

TEST(LightingCli, ProgressiveNeedsASamplingIntegrator) {
  const test::CommandResult result =
      test::runCli("render " + test::quoted(kMesh) + " -o /tmp/x.png --progressive 1 2>&1");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_TRUE(test::contains(result.output, "--integrator path")) << result.output;
}

TEST(LightingCli, ProgressiveIsAPositiveFiniteNumberOfSeconds) {
  for (const char* seconds : {"nan", "inf", "-1", "0"}) {
    const test::CommandResult result = test::runCli(
        "render " + test::quoted(kMesh) + " -o /tmp/x.png --integrator path --progressive " + seconds);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_TRUE(test::contains(result.output, std::string("--progressive: error: ") + seconds +
                                                  " is not a number of seconds > 0 (how often the image is "
                                                  "rewritten as it converges, e.g. 2)"))
        << result.output;
  }
}

TEST(LightingCli, ProgressiveEndsWithThePlainImage) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "lancer_progressive_test";
  std::filesystem::create_directories(folder);
  const std::string common =
      "render " + test::quoted(kMesh) + " --look sky --width 40 --height 30 --samples 8 -q";
  ASSERT_EQ(test::runCli(common + " -o " + test::quoted((folder / "plain.png").string())).exitCode, 0);
  ASSERT_EQ(
      test::runCli(common + " --progressive 0.001 -o " + test::quoted((folder / "progressive.png").string()))
          .exitCode,
      0);
  EXPECT_EQ(bytesOf(folder / "plain.png"), bytesOf(folder / "progressive.png"));
  std::filesystem::remove_all(folder);
}

TEST(LightingCli, ProgressiveWritesThroughThePlainRendersPipeline) {
  // Tone curve, exposure and the denoiser on a PNG, and an EXR with its layers: the last pass
  // written is the plain render's file, byte for byte.
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "lancer_progressive_pipeline";
  std::filesystem::create_directories(folder);
  const std::string common =
      "render " + test::quoted(kMesh) + " --look studio --width 40 --height 30 --samples 8 -q";
  for (const std::string& variant : {std::string("--tonemap aces --exposure 0.7 --denoise -o {}.png"),
                                     std::string("--denoise --aovs albedo,depth -o {}.exr")}) {
    auto named = [&](const char* name) {
      std::string command = variant;
      return command.replace(command.find("{}"), 2, (folder / name).string());
    };
    ASSERT_EQ(test::runCli(common + " " + named("plain")).exitCode, 0) << variant;
    ASSERT_EQ(test::runCli(common + " --progressive 0.000001 " + named("progressive")).exitCode, 0)
        << variant;
    const std::string extension = variant.substr(variant.size() - 4);
    const std::string plain = bytesOf(folder / ("plain" + extension));
    EXPECT_FALSE(plain.empty()) << variant;
    EXPECT_EQ(plain, bytesOf(folder / ("progressive" + extension))) << variant;
  }
  std::filesystem::remove_all(folder);
}

// Ctrl-C during --progressive: the file holds the last pass written (a whole picture), and the
// message says so instead of "was not written".
TEST(LightingCli, AnInterruptedProgressiveRenderSaysWhatTheFileHolds) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / "lancer_progressive_interrupt";
  std::filesystem::create_directories(folder);
  const std::string output = (folder / "out.png").string();
  const test::CommandResult result = test::runCli(
      "render " + test::quoted(kMesh) + " --look sky --width 160 --height 120 --samples 1024 -q" +
          " --progressive 0.000001 -o " + test::quoted(output),
      "timeout -s INT --preserve-status 1.5");
  EXPECT_EQ(result.exitCode, 130) << result.output;
  EXPECT_TRUE(
      test::contains(result.output, "lancer: interrupted; " + output + " holds the last pass written, "))
      << result.output;
  EXPECT_TRUE(test::contains(result.output, "samples per pixel of 1024")) << result.output;
  EXPECT_EQ(readPng(output).width(), 160);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace lancer
