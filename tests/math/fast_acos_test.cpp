// fastAcos against the double-precision acos over [-1, 1], the ends and the branch point included.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/math/fast_acos.hpp"

namespace lancer {
namespace {

TEST(FastAcos, WithinAFewFloatUlpsOfTheTrueAngleEverywhere) {
  double worst = 0;
  float worstAt = 0;
  constexpr int kSteps = 2000000;
  for (int i = 0; i <= kSteps; ++i) {
    const float x = -1.0f + 2.0f * static_cast<float>(i) / kSteps;
    const double error = std::fabs(double(fastAcos(x)) - std::acos(double(x)));
    if (error > worst) worst = error, worstAt = x;
  }
  // A float ulp at pi is 2.4e-7: a few of those at most.
  EXPECT_LT(worst, 6e-7) << "at " << worstAt;
}

TEST(FastAcos, ExactWhereTheAnglesAreSimple) {
  EXPECT_EQ(fastAcos(1.0f), 0.0f);
  EXPECT_FLOAT_EQ(fastAcos(0.0f), 1.5707963f);
  EXPECT_FLOAT_EQ(fastAcos(-1.0f), 3.1415927f);
  EXPECT_FLOAT_EQ(fastAcos(0.5f), 1.0471976f);
  EXPECT_FLOAT_EQ(fastAcos(-0.5f), 2.0943951f);
  EXPECT_FLOAT_EQ(fastAcos(std::nextafter(0.5f, 1.0f)), std::acos(std::nextafter(0.5f, 1.0f)));
}

}  // namespace
}  // namespace lancer
