// Geometry of one mesh face, a triangle or a quad (through its diagonals): normal, area, the signed
// volume of its cone from the origin, and the reversal of its winding.
#pragma once

#include <cstdint>
#include <span>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Geometric normal of a face (unit; for a quad, the normal of its diagonals' cross product, which is
// the mean plane's normal for a non-planar quad). Zero for a degenerate face. Inline: scene
// preparation computes it beside other per-face quantities from the same corners.
inline Vec3 faceNormal(std::span<const Vec3> positions, const MeshFace& face) {
  const Vec3& a = positions[face.vertex[0]];
  const Vec3& b = positions[face.vertex[1]];
  const Vec3& c = positions[face.vertex[2]];
  if (face.isQuad()) {
    const Vec3& d = positions[face.vertex[3]];
    return normalize(cross(c - a, d - b));
  }
  return normalize(cross(b - a, c - a));
}

// A face is degenerate as the renderer will see it (float positions) when its area is zero up to
// rounding: twice its area below 1e-12 times its longest edge squared (a NaN corner counts too). Both
// sides are compared squared, in double: no square root, no division, once per face of a
// million-face load. The reader drops such faces; so does a warp that collapses them.
namespace detail {
inline double maxOf(double a, double b) { return a > b ? a : b; }
}  // namespace detail

inline bool isDegenerateTriangle(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = b - a, bc = c - b, ca = a - c;
  const Vec3d normal = cross(ab, bc);  // = (b - a) x (c - a): twice the vector area
  const double longest = detail::maxOf(detail::maxOf(dot(ab, ab), dot(bc, bc)), dot(ca, ca));
  return !(dot(normal, normal) > 1e-24 * longest * longest);  // NaN counts as degenerate
}

inline bool isDegenerateQuad(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
  const Vec3d ab = b - a, bc = c - b, cd = d - c, da = a - d;
  const Vec3d normal = cross(c - a, d - b);  // twice the vector area of the quad (its diagonals)
  const double longest =
      detail::maxOf(detail::maxOf(dot(ab, ab), dot(bc, bc)), detail::maxOf(dot(cd, cd), dot(da, da)));
  return !(dot(normal, normal) > 1e-24 * longest * longest);
}

inline bool isDegenerateFace(const Vec3* p, const MeshFace& face) {
  const Vec3d a = toDouble(p[face.vertex[0]]);
  const Vec3d b = toDouble(p[face.vertex[1]]);
  const Vec3d c = toDouble(p[face.vertex[2]]);
  if (!face.isQuad()) return isDegenerateTriangle(a, b, c);
  return isDegenerateQuad(a, b, c, toDouble(p[face.vertex[3]]));
}

// Twice the vector area of a face, in double: the direction of its normal, with its winding, and
// twice its area as its length (a quad: the cross product of its diagonals, which in exact arithmetic
// is the sum of its two triangles' and Newell's normal, for a non-planar quad too). Zero for a
// degenerate face.
Vec3d twiceVectorArea(std::span<const Vec3> positions, const MeshFace& face);

// Area of a face in the frame of `positions`: half the length of twiceVectorArea.
double faceArea(std::span<const Vec3> positions, const MeshFace& face);

// Six times the signed volume of the cone from the origin over the face (its triple products, the
// triangles fanned from corner 0), in double. Summed over a closed shell it is six times the volume
// enclosed (divergence theorem), positive when the faces point out, wherever the origin; a shell of a
// million small faces still sums to the right sign, which is all shell orientation needs.
double sixfoldConeVolume(std::span<const Vec3> positions, const MeshFace& face);

// Reverses a face's winding (corner 0 stays first) and remaps its edge mask to the new edge order.
void reverseWinding(MeshFace& face, std::uint8_t& edgeMask);

}  // namespace lancer
