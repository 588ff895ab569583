// Clip intervals along rays: entering, leaving, parallel, several planes, and the plane a cap
// belongs to.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lancer/scene/clip_planes.hpp"

namespace lancer {
namespace {

const std::vector<ClipPlane> kKeepBelowZ1 = {{{0, 0, 1}, {0, 0, 1}}};  // removes z > 1

TEST(ClipPlanes, RayComingDownEntersAtThePlane) {
  const ClipInterval interval = clipRay(Ray({0, 0, 5}, {0, 0, -1}), kKeepBelowZ1);
  EXPECT_FLOAT_EQ(interval.enter, 4.0f);
  EXPECT_TRUE(std::isinf(interval.exit));
  EXPECT_EQ(interval.enterPlane, 0);
}

TEST(ClipPlanes, RayGoingUpLeavesAtThePlane) {
  const ClipInterval interval = clipRay(Ray({0, 0, -1}, {0, 0, 2}), kKeepBelowZ1);
  EXPECT_FLOAT_EQ(interval.enter, 0.0f);
  EXPECT_FLOAT_EQ(interval.exit, 1.0f);  // t in units of |direction| = 2
  EXPECT_EQ(interval.enterPlane, -1);
}

TEST(ClipPlanes, ParallelRaysAreKeptOrRemovedWhole) {
  EXPECT_FALSE(clipRay(Ray({0, 0, 0.5f}, {1, 0, 0}), kKeepBelowZ1).empty());
  EXPECT_TRUE(clipRay(Ray({0, 0, 1.5f}, {1, 0, 0}), kKeepBelowZ1).empty());
  EXPECT_TRUE(clipRay(Ray({0, 0, 3}, {0, 0, 1}), kKeepBelowZ1).empty());  // above, going away
}

TEST(ClipPlanes, TwoPlanesKeepTheirIntersectionAndNameTheCapPlane) {
  // Keep x <= 0 and y <= 0: a ray along the diagonal from (5, 3, 0) enters the quadrant when it
  // crosses x = 0, the later of the two planes.
  const std::vector<ClipPlane> planes = {{{0, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {1, 0, 0}}};
  const ClipInterval interval = clipRay(Ray({5, 3, 0}, {-1, -1, 0}), planes);
  EXPECT_FLOAT_EQ(interval.enter, 5.0f);
  EXPECT_EQ(interval.enterPlane, 1);
  EXPECT_TRUE(isClipped({0.1f, -1, 0}, planes));
  EXPECT_TRUE(isClipped({-1, 0.1f, 0}, planes));
  EXPECT_FALSE(isClipped({-1, -1, 7}, planes));
  EXPECT_FALSE(isClipped({0, 0, 0}, planes));  // on the plane is kept
}

TEST(ClipPlanes, NoPlanesKeepEverything) {
  const ClipInterval interval = clipRay(Ray({0, 0, 0}, {1, 2, 3}), {});
  EXPECT_EQ(interval.enter, 0.0f);
  EXPECT_TRUE(std::isinf(interval.exit));
  EXPECT_FALSE(isClipped({1e9f, 0, 0}, {}));
}

}  // namespace
}  // namespace lancer
