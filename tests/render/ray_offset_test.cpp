#include "lancer/render/ray_offset.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace lancer {
namespace {

// floatAbove is std::nextafter(x, +infinity), bit for bit, at zeros, denormals, the largest float,
// infinities and ordinary values of both signs.
TEST(RayOffset, FloatAboveIsNextafterUp) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const float values[] = {0.0f,
                          -0.0f,
                          std::numeric_limits<float>::denorm_min(),
                          -std::numeric_limits<float>::denorm_min(),
                          std::numeric_limits<float>::min(),
                          -std::numeric_limits<float>::min(),
                          std::numeric_limits<float>::max(),
                          -std::numeric_limits<float>::max(),
                          kInf,
                          -kInf,
                          1.0f,
                          -1.0f,
                          0.37f,
                          -812.5f,
                          3e7f};
  for (const float x : values) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(floatAbove(x)),
              std::bit_cast<std::uint32_t>(std::nextafter(x, kInf)))
        << x;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(-floatAbove(-x)),
              std::bit_cast<std::uint32_t>(std::nextafter(x, -kInf)))
        << x;
  }
  EXPECT_TRUE(std::isnan(floatAbove(std::numeric_limits<float>::quiet_NaN())));
}

// The offset point is on the normal's side of the surface, and the offset stays small relative to
// the coordinates, from tiny parts to survey coordinates.
TEST(RayOffset, MovesToTheNormalSideAtEveryScale) {
  for (float scale : {1e-3f, 1.0f, 1e3f, 1e6f}) {
    const Vec3 p{0.37f * scale, -0.81f * scale, 0.5f * scale};
    for (const Vec3& n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, normalize(Vec3{1, -2, 0.5f})}) {
      const Vec3 q = offsetRayOrigin(p, n);
      EXPECT_GT(dot(q - p, n), 0.0f) << "scale " << scale;
      EXPECT_LT(length(q - p), 1e-4f * scale + 1e-4f) << "scale " << scale;
    }
  }
}

}  // namespace
}  // namespace lancer
