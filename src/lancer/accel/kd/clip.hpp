// Bounds of a triangle clipped to a box ("perfect splits", Havran's thesis section 4.5 /
// Wald & Havran 2006 section 4.3): the SAH builder uses them for triangles that straddle a split.
#pragma once

#include <array>

#include "lancer/math/aabb.hpp"

namespace lancer {

// Box of the part of the triangle inside `box` (closed), empty if they do not meet. Clipping runs
// in double and the result is rounded outward (exact values stay exact), so it always contains the
// exact clipped triangle.
Aabb clippedTriangleBounds(const std::array<Vec3, 3>& corners, const Aabb& box);

}  // namespace lancer
