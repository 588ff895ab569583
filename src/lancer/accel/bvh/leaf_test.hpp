// A BVH leaf against one ray: its triangles eight at a time through the shared float half of the
// watertight test (accel/hit_query.hpp), each corner's coordinates picked from the leaf's vertex
// rows by one permute per row of eight vertices, the passing ones finished in order, so the answer
// is the scalar loop's.
#pragma once

#include <bit>
#include <cstdint>

#include "lancer/accel/bvh/leaf.hpp"
#include "lancer/accel/hit_query.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/util/isa.hpp"

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::bvh {
inline namespace LANCER_ISA_NS {

#ifdef LANCER_LEAF_AVX2

// Lane i: coordinate `axis` of corner c of triangle i, for the three corners (a leaf's rows hold at
// most kMaxLeafVertices = 24 vertices: up to three registers, the right one chosen by the index's
// upper bits; the permute reads only its low three).
inline void leafCoordinates(const BvhLeaf& leaf, __m256 (&coordinate)[9]) {
  static_assert(kMaxLeafVertices <= 24);
  const std::uint32_t vertexCount = leaf.vertexCount();
  const unsigned char* corners = leaf.corners();
  __m256i index[3];
  for (int c = 0; c < 3; ++c) {
    index[c] = _mm256_cvtepu8_epi32(
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(corners + c * std::size_t(leaf.count()))));
  }
  for (int axis = 0; axis < 3; ++axis) {
    const float* row = leaf.row(axis);
    const __m256 low = _mm256_loadu_ps(row);
    for (int c = 0; c < 3; ++c) coordinate[3 * c + axis] = _mm256_permutevar8x32_ps(low, index[c]);
    if (vertexCount > 8) {
      const __m256 middle = _mm256_loadu_ps(row + 8);
      for (int c = 0; c < 3; ++c) {
        const __m256 above = _mm256_castsi256_ps(_mm256_cmpgt_epi32(index[c], _mm256_set1_epi32(7)));
        coordinate[3 * c + axis] =
            _mm256_blendv_ps(coordinate[3 * c + axis], _mm256_permutevar8x32_ps(middle, index[c]), above);
      }
    }
    if (vertexCount > 16) {
      const __m256 high = _mm256_loadu_ps(row + 16);
      for (int c = 0; c < 3; ++c) {
        const __m256 above = _mm256_castsi256_ps(_mm256_cmpgt_epi32(index[c], _mm256_set1_epi32(15)));
        coordinate[3 * c + axis] =
            _mm256_blendv_ps(coordinate[3 * c + axis], _mm256_permutevar8x32_ps(high, index[c]), above);
      }
    }
  }
}

#endif

// Tests the leaf's triangles in order; true when the query stops (any hit).
template <typename Query>
inline bool testLeaf(const BvhLeaf& leaf, const Ray& ray, float tMin, float tMax, Query& query) {
  const std::uint32_t count = leaf.count();
#ifdef LANCER_LEAF_AVX2
  if (count >= accel::kMinSimdLeaf) {
    // The rows past the first line start where the vertex count, in the first, says: their lines
    // are asked for now rather than after that load.
    const auto* at = reinterpret_cast<const char*>(leaf.corners());
    _mm_prefetch(at + 64, _MM_HINT_T0);
    _mm_prefetch(at + 128, _MM_HINT_T0);
    __m256 coordinate[9];
    leafCoordinates(leaf, coordinate);
    accel::LeafCorners c;
    for (std::uint32_t passed = accel::sameSignCorners(coordinate, count, ray, c); passed != 0;
         passed &= passed - 1) {
      const int k = std::countr_zero(passed);
      if (query.finish(leaf.face(k), ray, tMin, tMax, c.ax[k], c.ay[k], c.az[k], c.bx[k], c.by[k], c.bz[k],
                       c.cx[k], c.cy[k], c.cz[k]))
        return true;
    }
    return false;
  }
#endif
  for (std::uint32_t i = 0; i < count; ++i) {
    if (query.test(leaf.triangle(i), ray, tMin, tMax)) return true;
  }
  return false;
}

}  // namespace LANCER_ISA_NS
}  // namespace lancer::bvh
