// The minimal result of a closest-hit query: distance, face and where on the hit triangle.
// Everything else (normals, material) is rebuilt once, for the closest hit only, by the renderer.
#pragma once

#include <cstdint>
#include <limits>

namespace lancer {

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  std::uint32_t face = 0xFFFFFFFFu;
  // Barycentric weights of corners 1 and 2 of the triangle hit (corner 0's is 1 - b1 - b2), from
  // the triangle test itself. For a quad the triangle is one of its halves (corners 0,1,2 or 0,2,3).
  float b1 = 0, b2 = 0;

  bool valid() const { return face != 0xFFFFFFFFu; }
};

// Ties (a ray through an edge shared by two faces) go to the lower face index, so that every
// accelerator returns the same face as the brute-force reference and images are identical.
inline bool closerThan(float t, std::uint32_t face, const Hit& best) {
  return t < best.t || (t == best.t && face < best.face);
}

}  // namespace lancer
