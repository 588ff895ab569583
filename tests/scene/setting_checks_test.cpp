// One wording per render setting, whoever names it: the scene file's key, the option, Python's
// argument; the limits are render_limits.hpp's.
#include "lancer/scene/setting_checks.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/input_errors.hpp"

namespace lancer {
namespace {

SettingName named(const std::string& name) { return {SourceLocation{name}, name}; }

TEST(SettingChecks, ValuesInRangeComeBack) {
  EXPECT_EQ(checkWidth(1, named("--width")), 1);
  EXPECT_EQ(checkHeight(32768, named("--height")), 32768);
  EXPECT_EQ(checkSamples(1024, named("samples")), 1024);
  EXPECT_EQ(checkMaxDepth(0, named("render.max_depth")), 0);
  EXPECT_EQ(checkThreads(0, named("--threads")), 0);
  EXPECT_EQ(checkFrames(10000, named("--frames")), 10000);
  EXPECT_EQ(checkBitDepth(16, named("--bit-depth")), 16);
  EXPECT_EQ(checkFps(0.01, named("--fps")), 0.01);
  EXPECT_EQ(checkLoop(-1, named("--loop")), -1);
  EXPECT_EQ(checkLoop(65535, named("loop")), 65535);
  EXPECT_EQ(checkExposure(-20, named("--exposure")), -20.0f);
  EXPECT_EQ(checkNoise(0.5, named("noise")), 0.5f);
  EXPECT_EQ(checkElevation(90, named("--elevation")), 90);
  EXPECT_EQ(checkAzimuth(-720, named("--azimuth")), -720);
  EXPECT_EQ(checkZoom(1000, named("--zoom")), 1000);
  checkSampleGrid(9, SamplerKind::Regular, IntegratorKind::Whitted, named("--samples"));
  checkSampleGrid(7, SamplerKind::Adaptive, IntegratorKind::Whitted, named("--samples"));
  checkSampleGrid(7, SamplerKind::Regular, IntegratorKind::Path, named("--samples"));
}

TEST(SettingChecks, OneWordingWhoeverNamesTheSetting) {
  EXPECT_EQ(test::messageOf([] { checkWidth(0, named("--width")); }),
            "--width: error: --width must be between 1 and 32768, found 0");
  EXPECT_EQ(test::messageOf([] {
              checkWidth(0, {SourceLocation{"scene.toml", 2, 9}, "render.width"});
            }),
            "scene.toml:2:9: error: render.width must be between 1 and 32768, found 0");
  EXPECT_EQ(test::messageOf([] { checkHeight(std::numeric_limits<std::int64_t>::max(), named("height")); }),
            "height: error: height must be between 1 and 32768, found 9223372036854775807");
  EXPECT_EQ(test::messageOf([] { checkSamples(0, named("samples")); }),
            "samples: error: samples must be between 1 and 1024, found 0");
  EXPECT_EQ(test::messageOf([] { checkMaxDepth(65, named("--max-depth")); }),
            "--max-depth: error: --max-depth must be between 0 and 64, found 65");
  EXPECT_EQ(test::messageOf([] { checkThreads(-1, named("threads")); }),
            "threads: error: threads must be between 0 and 1024 (0: one per usable CPU), found -1");
  EXPECT_EQ(test::messageOf([] { checkFrames(0, named("--frames")); }),
            "--frames: error: --frames must be between 1 and 10000, found 0");
  EXPECT_EQ(
      test::messageOf([] {
        checkFps(1000, {SourceLocation{"scene.toml", 4, 7}, "animation.fps"});
      }),
      "scene.toml:4:7: error: animation.fps must be a number of frames per second between 0.01 and 100, "
      "found 1000");
  EXPECT_EQ(test::messageOf([] { checkFps(std::numeric_limits<double>::quiet_NaN(), named("fps")); }),
            "fps: error: fps must be a number of frames per second between 0.01 and 100, found nan");
  EXPECT_EQ(test::messageOf([] { checkLoop(65536, named("loop")); }),
            "loop: error: loop must be between -1 and 65535 (0: forever, -1: play once), found 65536");
  EXPECT_EQ(test::messageOf([] { checkBitDepth(12, named("--bit-depth")); }),
            "--bit-depth: error: --bit-depth must be 8 or 16, found 12");
  EXPECT_EQ(
      test::messageOf([] { checkExposure(std::numeric_limits<double>::quiet_NaN(), named("exposure")); }),
      "exposure: error: exposure must be a number of stops between -20 and 20, found nan");
  EXPECT_EQ(test::messageOf([] {
              checkAdaptiveNoise(std::numeric_limits<double>::quiet_NaN(), named("--adaptive-noise"));
            }),
            "--adaptive-noise: error: --adaptive-noise must be greater than 0 and less than 1 (the error of "
            "the displayed value, a fraction of white, e.g. 0.01), found nan");
  EXPECT_EQ(test::messageOf([] { checkNoise(1, named("--noise")); }),
            "--noise: error: --noise must be greater than 0 and less than 1 (a relative error, e.g. 0.01), "
            "found 1");
  EXPECT_EQ(
      test::messageOf(
          [] { checkSampleGrid(8, SamplerKind::Stratified, IntegratorKind::Whitted, named("--samples")); }),
      "--samples: error: --samples must be a perfect square (an n x n sub-pixel grid) for the stratified "
      "sampler, found 8; use 4 or 9, or the adaptive sampler, or the path or ao integrator");
  EXPECT_EQ(test::messageOf([] { checkElevation(-91, named("--elevation")); }),
            "--elevation: error: --elevation must be a number of degrees between -90 and 90, found -91");
  EXPECT_EQ(test::messageOf([] { checkZoom(0, named("--zoom")); }),
            "--zoom: error: --zoom must be a factor between 0.001 and 1000, found 0");
  EXPECT_EQ(
      test::messageOf([] { checkAzimuth(std::numeric_limits<double>::infinity(), named("--azimuth")); }),
      "--azimuth: error: --azimuth must be a finite number of degrees, found inf");
}

}  // namespace
}  // namespace lancer
