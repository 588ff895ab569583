// The RMSE the benchmarks and convergence tests report, against values worked by hand.
#include "lancer/image/image_difference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace lancer {
namespace {

TEST(ImageDifference, IsZeroForOneImageAndIgnoresAlpha) {
  Image a(4, 3, Rgba{0.2f, 0.4f, 0.6f, 1});
  Image b = a;
  b.at(1, 1).a = 0;
  EXPECT_EQ(rootMeanSquareDifference(a, b), 0.0);
}

TEST(ImageDifference, AveragesSquaresOverChannelsAndPixels) {
  // One channel of one pixel of four differs by 0.6: sqrt(0.36 / 12).
  Image a(2, 2), b(2, 2);
  b.at(1, 0).g = 0.6f;
  EXPECT_NEAR(rootMeanSquareDifference(a, b), std::sqrt(0.36 / 12.0), 1e-7);
  // A uniform offset d in every channel gives d.
  Image c(3, 5, Rgba{0.1f, 0.1f, 0.1f, 1}), d(3, 5, Rgba{0.35f, 0.35f, 0.35f, 1});
  EXPECT_NEAR(rootMeanSquareDifference(c, d), 0.25, 1e-6);
}

TEST(ImageDifference, RefusesImagesOfDifferentSizes) {
  EXPECT_THROW(rootMeanSquareDifference(Image(2, 2), Image(2, 3)), std::invalid_argument);
  EXPECT_THROW(rootMeanSquareDifference(Image(), Image()), std::invalid_argument);
}

}  // namespace
}  // namespace lancer
