// Bounds of a triangle clipped to a box ("perfect splits", Havran's thesis section 4.5 /
// Wald & Havran 2006 section 4.3): the SAH builder uses them for triangles that straddle a split.
#pragma once

#include <array>

#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/aabb.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace lancer {

// Box of the part of the triangle inside `box` (closed), empty if they do not meet. Clipping runs
// in double and the result is rounded outward (exact values stay exact), so it always contains the
// exact clipped triangle.
Aabb clippedTriangleBounds(const std::array<Vec3, 3>& corners, const Aabb& box);

// Bounds of the parts of a triangle on each side of the plane x[axis] = plane: side 0 below, side 1
// above, each empty when the triangle has no part there. One plane instead of a cell's six: the
// binned builder intersects these with the bounds the triangle already has in the cell, which
// gives a box as tight as clipping to the cell for the usual straddler at a fraction of the cost.
// Same rounding as clippedTriangleBounds (outward, exact values exact).
void splitTriangleBounds(const std::array<Vec3, 3>& corners, int axis, float plane, Aabb& below, Aabb& above);

#if defined(__AVX2__)
// The same bounds, to the bit, in vectors (lanes x, y, z, then a lane to ignore): lower[0] and
// upper[0] below the plane, lower[1] and upper[1] above; an empty side has lower +inf, upper -inf.
// Half the cost: the binned build clips a million and a half straddlers on the 1M bench bracket.
void splitTriangleBounds(const PackedTriangle& triangle, int axis, float plane, __m128 lower[2],
                         __m128 upper[2]);
#endif

}  // namespace lancer
