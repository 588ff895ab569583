// Loops over faces that read or write per-vertex records ask for the records of the face a few
// faces ahead before they need them: a face's vertices are scattered over arrays bigger than the
// caches (gmsh numbers neither vertices nor faces in space order), and these loops have nothing
// else to wait for, so the misses of several faces overlap instead of following one another.
#pragma once

#include <cstddef>
#include <span>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

inline constexpr std::size_t kPrefetchFacesAhead = 8;

// The records of face f's first three corners (a quad's fourth is near them in memory more often
// than not), if there is a face f.
template <typename T>
void prefetchCorners(const T* perVertex, std::span<const MeshFace> faces, std::size_t f) {
  if (f >= faces.size()) return;
  for (int c = 0; c < 3; ++c) __builtin_prefetch(perVertex + faces[f].vertex[c]);
}

}  // namespace lancer
