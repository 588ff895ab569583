// A BVH leaf against one ray: its pre-gathered triangles eight at a time through the shared float
// half of the watertight test (accel/hit_query.hpp), the passing ones finished in
// order, so the answer is the scalar loop's.
#pragma once

#include <bit>
#include <cstdint>

#include "lancer/accel/hit_query.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/util/isa.hpp"

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::bvh {
inline namespace LANCER_ISA_NS {

// Tests `count` (1..8) triangles; true when the query stops (any hit).
template <typename Query>
inline bool testLeaf(const PackedTriangle* tri, std::uint32_t count, const Ray& ray, float tMin, float tMax,
                     Query& query) {
#ifdef LANCER_LEAF_AVX2
  if (count >= accel::kMinSimdLeaf) {
    const float* rows[8];
    for (std::uint32_t i = 0; i < 8; ++i) rows[i] = &tri[i < count ? i : 0].v0.x;
    accel::LeafCorners c;
    for (std::uint32_t passed = accel::sameSignTriangles(rows, count, ray, c); passed != 0;
         passed &= passed - 1) {
      const int k = std::countr_zero(passed);
      if (query.finish(tri[k], ray, tMin, tMax, c.ax[k], c.ay[k], c.az[k], c.bx[k], c.by[k], c.bz[k], c.cx[k],
                       c.cy[k], c.cz[k]))
        return true;
    }
    return false;
  }
#endif
  for (std::uint32_t i = 0; i < count; ++i) {
    if (query.test(tri[i], ray, tMin, tMax)) return true;
  }
  return false;
}

}  // namespace LANCER_ISA_NS
}  // namespace lancer::bvh
