#include "lancer/render/ray_offset.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lancer {
namespace {

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
