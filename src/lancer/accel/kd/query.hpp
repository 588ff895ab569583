// What the kd-tree's traversals add to the shared query bookkeeping (accel/hit_query.hpp): the
// mailbox of recently tested triangles and the eight-triangle test of triangles in the layout.
#pragma once

#include <cstdint>

#include "lancer/accel/hit_query.hpp"
#include "lancer/accel/kd/node.hpp"
#include "lancer/util/isa.hpp"

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::kd {
inline namespace LANCER_ISA_NS {

// Recently tested triangles, direct-mapped by index: neighbouring leaves share triangles (a kd leaf
// refers to triangles, a BVH leaf holds its own).
constexpr std::uint32_t kMailboxSize = 8;

#ifdef LANCER_LEAF_AVX2

using accel::sameSignTriangles;

// accel::sameSignTriangles for triangles at the kd layout's word offsets `offsets`.
inline std::uint32_t sameSignTriangles(const KdNode* base, const std::uint32_t* offsets, std::uint32_t count,
                                       const Ray& ray, accel::LeafCorners& out) {
  const float* tri[8];
  for (std::uint32_t i = 0; i < 8; ++i)
    tri[i] = reinterpret_cast<const float*>(base + offsets[i < count ? i : 0]);
  return sameSignTriangles(tri, count, ray, out);
}

#endif  // LANCER_LEAF_AVX2

}  // namespace LANCER_ISA_NS
}  // namespace lancer::kd
