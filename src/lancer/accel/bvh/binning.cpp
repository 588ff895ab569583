#include "lancer/accel/bvh/binning.hpp"

#include <cstddef>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "lancer/util/isa.hpp"

namespace lancer::bvh {

static_assert(offsetof(PrimRef, face) == 3 * sizeof(float) && offsetof(PrimRef, hi) == 4 * sizeof(float));

template <typename Isa>
void fillBins(const PrimRef* refs, std::size_t begin, std::size_t end, const BinGrid& grid, float* box,
              std::uint32_t* triangles) {
#if defined(__SSE2__)
  const __m128 origin = _mm_load_ps(grid.origin), scale = _mm_load_ps(grid.scale);
  const __m128 zero = _mm_setzero_ps(), last = _mm_set1_ps(grid.last);
  for (std::size_t i = begin; i < end; ++i) {
    const PrimRef& r = refs[i];
    const float* p = r.lo;  // lo, face, hi, triangles: 32 bytes
    // The bin on each axis, as Grid::bin: ((lo + hi) - origin) * scale, maxps 0, minps last, truncated.
    const __m128 lo = _mm_loadu_ps(p), hi = _mm_loadu_ps(p + 4);
    const __m128i b = _mm_cvttps_epi32(
        _mm_min_ps(_mm_max_ps(_mm_mul_ps(_mm_sub_ps(_mm_add_ps(lo, hi), origin), scale), zero), last));
#if defined(__AVX2__)
    // The reference as one register (lo, face, hi, triangles); a bin's lanes 0-3 take the min, 4-7
    // the max (the face and triangle lanes are never read).
    const __m256 whole = _mm256_loadu_ps(p);
    const int bx = _mm_cvtsi128_si32(b), by = _mm_extract_epi32(b, 1), bz = _mm_extract_epi32(b, 2);
    auto grow = [&](float* e) {
      const __m256 cur = _mm256_loadu_ps(e);
      _mm256_storeu_ps(e, _mm256_blend_ps(_mm256_min_ps(cur, whole), _mm256_max_ps(cur, whole), 0xF0));
    };
    grow(box + (0 * kMaxBins + bx) * 8);
    grow(box + (1 * kMaxBins + by) * 8);
    grow(box + (2 * kMaxBins + bz) * 8);
    triangles[bx * 4 + 0] += r.triangles;
    triangles[by * 4 + 1] += r.triangles;
    triangles[bz * 4 + 2] += r.triangles;
#else
    alignas(16) int bins[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bins), b);
    for (int a = 0; a < 3; ++a) {
      float* e = box + (a * kMaxBins + bins[a]) * 8;
      _mm_storeu_ps(e, _mm_min_ps(_mm_loadu_ps(e), lo));
      _mm_storeu_ps(e + 4, _mm_max_ps(_mm_loadu_ps(e + 4), hi));
      triangles[bins[a] * 4 + a] += r.triangles;
    }
#endif
  }
#else
  // The same operations lane by lane (minps / maxps: the second operand when the comparison fails).
  for (std::size_t i = begin; i < end; ++i) {
    const PrimRef& r = refs[i];
    for (int a = 0; a < 3; ++a) {
      float x = (r.lo[a] + r.hi[a] - grid.origin[a]) * grid.scale[a];
      x = x > 0.0f ? x : 0.0f;
      x = x < grid.last ? x : grid.last;
      const int bin = static_cast<int>(x);
      float* e = box + (a * kMaxBins + bin) * 8;
      for (int k = 0; k < 3; ++k) {
        e[k] = e[k] < r.lo[k] ? e[k] : r.lo[k];
        e[4 + k] = e[4 + k] > r.hi[k] ? e[4 + k] : r.hi[k];
      }
      triangles[bin * 4 + a] += r.triangles;
    }
  }
#endif
}

template void fillBins<LANCER_ISA_TAG>(const PrimRef*, std::size_t, std::size_t, const BinGrid&, float*,
                                       std::uint32_t*);

}  // namespace lancer::bvh
