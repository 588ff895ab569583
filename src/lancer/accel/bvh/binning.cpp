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
#if defined(__AVX2__)
  // Two references at a time: their bins in one 256-bit register (the same operations lane by lane as
  // Grid::bin), then each reference as one register (lo, face, hi, triangles) grows a bin's lanes 0-3
  // by min and 4-7 by max (the face and triangle lanes are never read).
  const __m256 origin = _mm256_broadcast_ps(reinterpret_cast<const __m128*>(grid.origin));
  const __m256 scale = _mm256_broadcast_ps(reinterpret_cast<const __m128*>(grid.scale));
  const __m256 zero = _mm256_setzero_ps(), last = _mm256_set1_ps(grid.last);
  auto grow = [&](float* e, __m256 whole) {
    const __m256 cur = _mm256_loadu_ps(e);
    _mm256_storeu_ps(e, _mm256_blend_ps(_mm256_min_ps(cur, whole), _mm256_max_ps(cur, whole), 0xF0));
  };
  auto add = [&](const PrimRef& r, __m256 whole, const int* b) {
    grow(box + (0 * kMaxBins + b[0]) * 8, whole);
    grow(box + (1 * kMaxBins + b[1]) * 8, whole);
    grow(box + (2 * kMaxBins + b[2]) * 8, whole);
    triangles[b[0] * 4 + 0] += r.triangles;
    triangles[b[1] * 4 + 1] += r.triangles;
    triangles[b[2] * 4 + 2] += r.triangles;
  };
  std::size_t i = begin;
  for (; i + 2 <= end; i += 2) {
    const __m256 r0 = _mm256_loadu_ps(refs[i].lo), r1 = _mm256_loadu_ps(refs[i + 1].lo);
    const __m256 lo = _mm256_permute2f128_ps(r0, r1, 0x20), hi = _mm256_permute2f128_ps(r0, r1, 0x31);
    alignas(32) int b[8];
    _mm256_store_si256(
        reinterpret_cast<__m256i*>(b),
        _mm256_cvttps_epi32(_mm256_min_ps(
            _mm256_max_ps(_mm256_mul_ps(_mm256_sub_ps(_mm256_add_ps(lo, hi), origin), scale), zero), last)));
    add(refs[i], r0, b);
    add(refs[i + 1], r1, b + 4);
  }
  for (; i < end; ++i) {
    const __m256 r = _mm256_loadu_ps(refs[i].lo);
    const __m256 both = _mm256_permute2f128_ps(r, r, 0x01);  // hi, lo
    alignas(32) int b[8];
    _mm256_store_si256(
        reinterpret_cast<__m256i*>(b),
        _mm256_cvttps_epi32(_mm256_min_ps(
            _mm256_max_ps(_mm256_mul_ps(_mm256_sub_ps(_mm256_add_ps(r, both), origin), scale), zero), last)));
    add(refs[i], r, b);
  }
#elif defined(__SSE2__)
  const __m128 origin = _mm_load_ps(grid.origin), scale = _mm_load_ps(grid.scale);
  const __m128 zero = _mm_setzero_ps(), last = _mm_set1_ps(grid.last);
  for (std::size_t i = begin; i < end; ++i) {
    const PrimRef& r = refs[i];
    // The bin on each axis, as Grid::bin: ((lo + hi) - origin) * scale, maxps 0, minps last, truncated.
    const __m128 lo = _mm_loadu_ps(r.lo), hi = _mm_loadu_ps(r.hi);
    alignas(16) int bins[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bins),
                    _mm_cvttps_epi32(_mm_min_ps(
                        _mm_max_ps(_mm_mul_ps(_mm_sub_ps(_mm_add_ps(lo, hi), origin), scale), zero), last)));
    for (int a = 0; a < 3; ++a) {
      float* e = box + (a * kMaxBins + bins[a]) * 8;
      _mm_storeu_ps(e, _mm_min_ps(_mm_loadu_ps(e), lo));
      _mm_storeu_ps(e + 4, _mm_max_ps(_mm_loadu_ps(e + 4), hi));
      triangles[bins[a] * 4 + a] += r.triangles;
    }
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
