#include "lancer/render/edge_overlay.hpp"

#include <algorithm>
#include <cmath>

namespace lancer {

float rayToSegmentDistance(const Vec3& origin, const Vec3& unitDirection, const Vec3& a, const Vec3& b) {
  // Remove the components along the ray: what is left is the segment projected onto the plane
  // across the ray, where the closest point is a clamped 1D projection.
  const Vec3 w = a - origin, e = b - a;
  const Vec3 wAcross = w - unitDirection * dot(w, unitDirection);
  const Vec3 eAcross = e - unitDirection * dot(e, unitDirection);
  const float eLength2 = dot(eAcross, eAcross);
  const float u = eLength2 > 0.0f ? std::clamp(-dot(wAcross, eAcross) / eLength2, 0.0f, 1.0f) : 0.0f;
  return length(wAcross + eAcross * u);
}

float edgeCoverage(const Vec3& origin, const Vec3& unitDirection, const Vec3* corners, int cornerCount,
                   std::uint8_t edgeMask, std::uint8_t lineCornerMask, float pixelSize, float widthPixels) {
  if ((edgeMask | lineCornerMask) == 0 || !(pixelSize > 0.0f)) return 0.0f;
  float nearest = INFINITY;
  for (int i = 0; i < cornerCount; ++i) {
    if (edgeMask & (1u << i))
      nearest = std::min(
          nearest, rayToSegmentDistance(origin, unitDirection, corners[i], corners[(i + 1) % cornerCount]));
    else if (lineCornerMask & (1u << i))
      nearest = std::min(nearest, rayToSegmentDistance(origin, unitDirection, corners[i], corners[i]));
  }
  return lineCoverage(nearest / pixelSize, widthPixels);
}

}  // namespace lancer
