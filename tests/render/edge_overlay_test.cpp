// Edge coverage: distances across the ray, width in pixels at any distance, the mask.
#include <gtest/gtest.h>

#include "lancer/render/edge_overlay.hpp"

namespace lancer {
namespace {

TEST(EdgeOverlay, RayToSegmentDistanceIsMeasuredAcrossTheRay) {
  const Vec3 down{0, 0, -1};
  // A segment on the plane z = 0 from (1,-1) to (1,1): 1 away from a ray down the z axis, whatever
  // the segment's depth along the ray.
  EXPECT_FLOAT_EQ(rayToSegmentDistance({0, 0, 5}, down, {1, -1, 0}, {1, 1, 0}), 1.0f);
  EXPECT_FLOAT_EQ(rayToSegmentDistance({0, 0, 5}, down, {1, -1, -3}, {1, 1, 7}), 1.0f);
  // Past the segment's end the distance is to the end point.
  EXPECT_FLOAT_EQ(rayToSegmentDistance({0, 0, 5}, down, {3, 4, 0}, {3, 9, 0}), 5.0f);
  // A segment along the ray collapses to a point.
  EXPECT_FLOAT_EQ(rayToSegmentDistance({0, 0, 5}, down, {0, 2, 0}, {0, 2, -4}), 2.0f);
}

TEST(EdgeOverlay, CoverageIsOneOnTheLineAndFadesOverOnePixel) {
  const Vec3 corners[3] = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
  const Vec3 down{0, 0, -1};
  const float pixel = 0.1f, width = 2.0f;  // the line is 0.2 wide, centred on the edge
  auto coverageAt = [&](float x, float y) {
    return edgeCoverage({x, y, 1}, down, corners, 3, 0x1, 0, pixel, width);
  };
  EXPECT_FLOAT_EQ(coverageAt(5, 0.0f), 1.0f);
  EXPECT_FLOAT_EQ(coverageAt(5, 0.05f), 1.0f);
  EXPECT_NEAR(coverageAt(5, 0.1f), 0.5f, 1e-5f);  // the line's border: half covered
  EXPECT_FLOAT_EQ(coverageAt(5, 0.16f), 0.0f);
  // Only edge 0 (corner 0 to 1) is marked: the other two edges draw nothing.
  EXPECT_FLOAT_EQ(edgeCoverage({0.0f, 5, 1}, down, corners, 3, 0x1, 0, pixel, width), 0.0f);
  EXPECT_FLOAT_EQ(edgeCoverage({0.0f, 5, 1}, down, corners, 3, 0x4, 0, pixel, width), 1.0f);
}

TEST(EdgeOverlay, LinesKeepTheirPixelWidthAtAnyDistance) {
  // The same edge seen by a perspective camera near and far: with the footprint growing with the
  // distance, the coverage at the same angular offset is the same.
  const PixelFootprint perspective{0, 0.002f};
  const Vec3 corners[4] = {{-1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 1, 0}};
  for (float distance : {1.0f, 10.0f, 100.0f}) {
    const Vec3 origin{0, -distance * 0.003f, distance};  // 1.5 pixels off the edge, seen from above
    const float coverage =
        edgeCoverage(origin, {0, 0, -1}, corners, 4, 0x1, 0, perspective.at(distance), 2.0f);
    EXPECT_NEAR(coverage, 0.0f, 1e-5f) << distance;
    const Vec3 closer{0, -distance * 0.0018f, distance};  // 0.9 pixel off: inside a 2-pixel line
    EXPECT_NEAR(edgeCoverage(closer, {0, 0, -1}, corners, 4, 0x1, 0, perspective.at(distance), 2.0f), 0.6f,
                1e-3f);
  }
}

TEST(EdgeOverlay, CornersOnALineDrawItsRoundEnd) {
  // A triangle that touches a line only at corner 0: near that corner it draws the line's end,
  // elsewhere nothing.
  const Vec3 corners[3] = {{0, 0, 0}, {1, 1, 0}, {-1, 1, 0}};
  const Vec3 down{0, 0, -1};
  EXPECT_FLOAT_EQ(edgeCoverage({0, 0.05f, 1}, down, corners, 3, 0, 0x1, 0.1f, 2.0f), 1.0f);
  EXPECT_FLOAT_EQ(edgeCoverage({0, 0.5f, 1}, down, corners, 3, 0, 0x1, 0.1f, 2.0f), 0.0f);
  EXPECT_FLOAT_EQ(edgeCoverage({0, 0.05f, 1}, down, corners, 3, 0, 0x0, 0.1f, 2.0f), 0.0f);
}

TEST(EdgeOverlay, NothingWithoutMaskOrFootprint) {
  const Vec3 corners[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(edgeCoverage({0, 0, 1}, {0, 0, -1}, corners, 3, 0, 0, 0.1f, 1), 0.0f);
  EXPECT_EQ(edgeCoverage({0, 0, 1}, {0, 0, -1}, corners, 3, 0x7, 0x7, 0.0f, 1), 0.0f);
}

}  // namespace
}  // namespace lancer
