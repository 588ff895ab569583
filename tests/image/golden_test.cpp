// The golden-image helper that every module's tests use: PSNR, pass/fail, failure artefacts, and
// regeneration with LANCER_UPDATE_GOLDEN=1.
#include "support/golden.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "lancer/image/image_io.hpp"
#include "support/files.hpp"
#include "support/scoped_env.hpp"

namespace lancer {
namespace {

using test::ScratchFolder;

Image ramp() {
  Image image(16, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) image.at(x, y) = {x / 15.0f, y / 7.0f, 0.5f, 1};
  return image;
}

using test::ScopedEnv;

TEST(Psnr, IsInfiniteForEqualImagesAndMatchesTheFormula) {
  EXPECT_TRUE(std::isinf(test::psnr8(ramp(), ramp())));
  Image changed = ramp();
  changed.at(0, 0).r = 10.0f / 255.0f;  // one sample off by 10 of 16 * 8 * 3
  const double mse = 100.0 / (16 * 8 * 3);
  EXPECT_NEAR(test::psnr8(changed, ramp()), 10 * std::log10(255.0 * 255.0 / mse), 1e-9);
  // Alpha counts once either image has transparency.
  Image transparent = ramp();
  transparent.at(1, 1).a = 0;
  EXPECT_NEAR(test::psnr8(transparent, ramp()),
              10 * std::log10(255.0 * 255.0 / (255.0 * 255.0 / (16 * 8 * 4))), 1e-9);
}

TEST(ExpectImageNear, PassesAgainstItsOwnPng) {
  ScratchFolder folder;
  writePng(folder.file("golden.png"), ramp());
  test::expectImageNear(ramp(), folder.file("golden.png"), 60.0);
}

TEST(ExpectImageNear, FailureWritesActualExpectedAndDifference) {
  ScratchFolder folder;
  ScopedEnv failures("LANCER_GOLDEN_FAILURE_DIR", folder.file("failures"));
  writePng(folder.file("golden.png"), ramp());
  Image changed = ramp();
  for (int x = 0; x < 16; ++x) changed.at(x, 3) = {1, 0, 1, 1};
  EXPECT_NONFATAL_FAILURE(test::expectImageNear(changed, folder.file("golden.png"), 30.0),
                          "difference.png (|actual - expected| x 8)");
  const std::string where = folder.file("failures/ExpectImageNear.FailureWritesActualExpectedAndDifference/");
  EXPECT_TRUE(std::isinf(test::psnr8(readPng(where + "actual.png"), changed)));
  EXPECT_TRUE(std::isinf(test::psnr8(readPng(where + "expected.png"), ramp())));
  const Image difference = readPng(where + "difference.png");
  EXPECT_EQ(encode8(difference.at(0, 0).r), 0);
  EXPECT_EQ(encode8(difference.at(0, 3).g), std::min(255, 8 * encode8(ramp().at(0, 3).g)));
}

TEST(ExpectImageNear, MissingGoldenFileFailsWithTheWayToCreateIt) {
  ScratchFolder folder;
  ScopedEnv failures("LANCER_GOLDEN_FAILURE_DIR", folder.file("failures"));
  EXPECT_NONFATAL_FAILURE(test::expectImageNear(ramp(), folder.file("none.png"), 30.0),
                          "run the test with LANCER_UPDATE_GOLDEN=1");
}

TEST(ExpectImageNear, SizeMismatchFails) {
  ScratchFolder folder;
  ScopedEnv failures("LANCER_GOLDEN_FAILURE_DIR", folder.file("failures"));
  writePng(folder.file("golden.png"), Image(4, 4));
  EXPECT_NONFATAL_FAILURE(test::expectImageNear(ramp(), folder.file("golden.png"), 30.0),
                          "actual 16x8, expected 4x4");
}

TEST(ExpectImageNear, UpdateModeRewritesTheGoldenFile) {
  ScratchFolder folder;
  writePng(folder.file("golden.png"), Image(4, 4));
  {
    ScopedEnv update("LANCER_UPDATE_GOLDEN", "1");
    EXPECT_TRUE(test::updatingGoldenFiles());
    test::expectImageNear(ramp(), folder.file("golden.png"), 99.0);
  }
  EXPECT_TRUE(std::isinf(test::psnr8(readPng(folder.file("golden.png")), ramp())));
  ScopedEnv notOne("LANCER_UPDATE_GOLDEN", "0");
  EXPECT_FALSE(test::updatingGoldenFiles());
}

}  // namespace
}  // namespace lancer
