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
