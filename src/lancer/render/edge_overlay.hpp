// Element edges drawn over the shaded surface (`edges = {...}` per mesh): how much of a pixel an
// edge of the hit face covers, measured across the ray so lines keep their width in pixels near
// and far, on oblique faces, and in reflections.
#pragma once

#include <cstdint>

#include "lancer/math/ray.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// World size of one pixel at distance t along a ray: base + perDistance * t. A perspective camera
// has base 0 and perDistance = the pixel's angle; an orthographic one the reverse.
struct PixelFootprint {
  float base = 0;
  float perDistance = 0;
  float at(float distance) const { return base + perDistance * distance; }
};

// Distance from the line through `origin` along unit `direction` to the segment [a, b]: the
// screen-space distance (times the footprint) between the pixel and the edge's projection.
float rayToSegmentDistance(const Vec3& origin, const Vec3& unitDirection, const Vec3& a, const Vec3& b);

// Coverage of a line `widthPixels` wide at `distancePixels` from its centre line: 1 on the line, 0
// beyond half a pixel outside it, linear in between (a box filter).
inline float lineCoverage(float distancePixels, float widthPixels) {
  const float c = 0.5f * widthPixels + 0.5f - distancePixels;
  return c < 0.0f ? 0.0f : (c > 1.0f ? 1.0f : c);
}

// Coverage in [0, 1] of a line `widthPixels` wide along the marked edges (bit i: corner i to corner
// i+1) of a face with `cornerCount` corners, for a ray whose pixel is `pixelSize` world units wide
// at the hit: 1 on the line, 0 beyond half a pixel outside it, linear in between (a box-filtered
// edge, so one sample per pixel already draws smooth lines). `lineCornerMask` (bit i: corner i)
// marks corners that lie on a line drawn by other faces: a face touching a line only at a corner
// (the middle triangle of a split 6-node triangle) draws the line's round end there, or the line
// would show a notch.
float edgeCoverage(const Vec3& origin, const Vec3& unitDirection, const Vec3* corners, int cornerCount,
                   std::uint8_t edgeMask, std::uint8_t lineCornerMask, float pixelSize, float widthPixels);

}  // namespace lancer
