// The minimal result of a closest-hit query: distance and face. Everything else (surface
// coordinates, normals, material) is rebuilt once, for the closest hit only, by the renderer.
#pragma once

#include <cstdint>
#include <limits>

namespace lancer {

struct Hit {
  float t = std::numeric_limits<float>::infinity();
  std::uint32_t face = 0xFFFFFFFFu;

  bool valid() const { return face != 0xFFFFFFFFu; }
};

// Ties (a ray through an edge shared by two faces) go to the lower face index, so that every
// accelerator returns the same face as the brute-force reference and images are identical.
inline bool closerThan(float t, std::uint32_t face, const Hit& best) {
  return t < best.t || (t == best.t && face < best.face);
}

}  // namespace lancer
