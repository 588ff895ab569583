// The partition step of the default kd build (kd/binned_build.cpp): a cell's references sent to the
// side(s) of its split plane, a straddler clipped to each side, and the children's cells.
#pragma once

#include <algorithm>
#include <cstdint>

#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/util/prefetch.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace lancer::binned {

// The children's cells, and the bounds of what each side received.
struct Children {
  Cell left, right;
  std::size_t leftCount = 0, rightCount = 0;
};

// Sends each of refs[0, n) to the side(s) of the plane it lies on: right ones to right[], left ones
// to left[] (right may be refs itself: it is written no faster than refs is read). A reference
// crossing the plane goes to both sides with the bounds of the triangle's part there (one-plane
// clip, see splitTriangleBounds), or, below KdBuildOptions::clipAboveFraction, its box cut at the
// plane; a side where it has no part gets none.
struct Partitioner {
  const KdBuildInput& input;
  const KdBuildOptions& options;
  const Split& split;
  const Box& cell;

  bool clips(const Ref& r) const {
    if (options.clipAboveFraction <= 0.0f) return true;
    for (const int other : {(split.axis + 1) % 3, (split.axis + 2) % 3}) {
      if (r.hi[other] - r.lo[other] >= options.clipAboveFraction * (cell.hi[other] - cell.lo[other]))
        return true;
    }
    return false;
  }

  // The parts of a straddler on each side; false for a side where it has none.
  void cut(const Ref& r, Ref& l, Ref& rr, bool& keepLeft, bool& keepRight) const {
    const int k = split.axis;
    const float p = split.pos;
    l = r;
    rr = r;
    l.hi[k] = p;
    rr.lo[k] = p;
    keepLeft = keepRight = true;
    if (!clips(r)) return;
#if defined(__AVX2__)
    __m128 lower[2], upper[2];
    splitTriangleBounds(input.triangles[r.id], k, p, lower, upper);
    // l := l ∩ below, rr := rr ∩ above, lanes 0-2 the lower bounds, 3-5 the upper (as intersect).
    const __m256i gather = _mm256_setr_epi32(0, 1, 2, 4, 5, 6, 3, 7);
    const __m256i toLow = _mm256_setr_epi32(3, 4, 5, 0, 1, 2, 6, 7);
    const __m256 lowLanes = _mm256_castsi256_ps(_mm256_setr_epi32(-1, -1, -1, 0, 0, 0, 0, 0));
    const __m256 highLanes = _mm256_castsi256_ps(_mm256_setr_epi32(0, 0, 0, -1, -1, -1, 0, 0));
    auto cutTo = [&](Ref& part, __m128 lo, __m128 hi) {
      const __m256 v = _mm256_load_ps(part.lo);
      const __m256 box = _mm256_permutevar8x32_ps(_mm256_set_m128(hi, lo), gather);
      __m256 out = _mm256_blendv_ps(v, _mm256_max_ps(box, v), lowLanes);
      out = _mm256_blendv_ps(out, _mm256_min_ps(box, v), highLanes);
      _mm256_store_ps(part.lo, out);
      const __m256 ordered = _mm256_cmp_ps(out, _mm256_permutevar8x32_ps(out, toLow), _CMP_LE_OQ);
      return (_mm256_movemask_ps(ordered) & 7) == 7;
    };
    keepLeft = cutTo(l, lower[0], upper[0]);
    keepRight = cutTo(rr, lower[1], upper[1]);
#else
    Aabb below, above;
    splitTriangleBounds(cornersOf(input.triangles[r.id]), k, p, below, above);
    keepLeft = intersect(l, below);
    keepRight = intersect(rr, above);
#endif
  }

  void operator()(const Ref* refs, std::size_t n, Ref* right, Ref* left, Children& out) const {
    Box usedLeft, usedRight;
    const auto [nl, nr] = partition<true>(refs, n, right, left, usedLeft, usedRight);
    out.left.used.extend(usedLeft);
    out.right.used.extend(usedRight);
    out.leftCount += nl;
    out.rightCount += nr;
  }

  // The same sides for a small cell's references, without the bounds of each side (small cells'
  // splits do not use them) or prefetching (their triangles are few and near). Returns the counts.
  std::pair<std::size_t, std::size_t> small(const Ref* refs, std::size_t n, Ref* right, Ref* left) const {
    Box unused;
    return partition<false>(refs, n, right, left, unused, unused);
  }

  // The loop of both: with kBig, prefetching straddlers' triangles and the bounds of each side's
  // references (in usedLeft, usedRight). Returns the counts.
  template <bool kBig>
  std::pair<std::size_t, std::size_t> partition(const Ref* refs, std::size_t n, Ref* right, Ref* left,
                                                Box& usedLeft, Box& usedRight) const {
    const int k = split.axis;
    const float p = split.pos;
    const PackedTriangle* triangles = input.triangles.data();
    // Straddlers read their triangle, usually a cache miss (it was last read levels above): fetched
    // this many references ahead, the first ones all at once before the loop (branch-free: a
    // non-straddler prefetches its own reference).
    constexpr std::size_t kAhead = 16;
    auto prefetch = [&](std::size_t i) {
      const Ref& a = refs[i];
      const bool straddles = a.lo[k] < p && a.hi[k] > p;
      const char* triangle = reinterpret_cast<const char*>(triangles + a.id);
      const char* self = reinterpret_cast<const char*>(&a);
      prefetchLine(straddles ? triangle : self);
      prefetchLine(straddles ? triangle + sizeof(PackedTriangle) - 1 : self);
    };
    if constexpr (kBig) {
      for (std::size_t i = 0; i < std::min(n, kAhead); ++i) prefetch(i);
    }
    std::size_t nl = 0, nr = 0;
#if defined(__AVX2__)
    // Bounds of each side's references as vectors: lanes 0-2 of the minimum, 3-5 of the maximum.
    __m256 minLeft = _mm256_set1_ps(std::numeric_limits<float>::max()), maxLeft = -minLeft;
    __m256 minRight = minLeft, maxRight = maxLeft;
    auto extendLeft = [&](__m256 v) {
      minLeft = _mm256_min_ps(minLeft, v);
      maxLeft = _mm256_max_ps(maxLeft, v);
    };
    auto extendRight = [&](__m256 v) {
      minRight = _mm256_min_ps(minRight, v);
      maxRight = _mm256_max_ps(maxRight, v);
    };
#endif
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (kBig) {
        if (i + kAhead < n) prefetch(i + kAhead);
      }
      const float lo = refs[i].lo[k], hi = refs[i].hi[k];
      const bool planar = lo == hi && lo == p;
      const bool toLeft = planar ? split.planarLeft : hi <= p;
      const bool toRight = planar ? !split.planarLeft : lo >= p;
      if (toLeft || toRight) {
        // One side: written to both, kept by the count of one (a branch here mispredicts often).
#if defined(__AVX2__)
        const __m256 v = _mm256_load_ps(refs[i].lo);
        _mm256_store_ps(left[nl].lo, v);
        _mm256_store_ps(right[nr].lo, v);
        if constexpr (kBig) {
          const __m256 side = _mm256_castsi256_ps(_mm256_set1_epi32(toLeft ? -1 : 0));
          minLeft = _mm256_blendv_ps(minLeft, _mm256_min_ps(minLeft, v), side);
          maxLeft = _mm256_blendv_ps(maxLeft, _mm256_max_ps(maxLeft, v), side);
          minRight = _mm256_blendv_ps(_mm256_min_ps(minRight, v), minRight, side);
          maxRight = _mm256_blendv_ps(_mm256_max_ps(maxRight, v), maxRight, side);
        }
#else
        const Ref r = refs[i];
        left[nl] = r;
        right[nr] = r;
        if constexpr (kBig) (toLeft ? usedLeft : usedRight).extend(r);
#endif
        nl += toLeft;
        nr += toRight;
        continue;
      }
      Ref l, rr;
      bool keepLeft, keepRight;
      cut(refs[i], l, rr, keepLeft, keepRight);
      if (keepLeft) {
        left[nl++] = l;
        if constexpr (kBig) {
#if defined(__AVX2__)
          extendLeft(_mm256_load_ps(l.lo));
#else
          usedLeft.extend(l);
#endif
        }
      }
      if (keepRight) {
        right[nr++] = rr;
        if constexpr (kBig) {
#if defined(__AVX2__)
          extendRight(_mm256_load_ps(rr.lo));
#else
          usedRight.extend(rr);
#endif
        }
      }
    }
#if defined(__AVX2__)
    if constexpr (kBig) {
      alignas(32) float minL[8], maxL[8], minR[8], maxR[8];
      _mm256_store_ps(minL, minLeft);
      _mm256_store_ps(maxL, maxLeft);
      _mm256_store_ps(minR, minRight);
      _mm256_store_ps(maxR, maxRight);
      for (int j = 0; j < 3; ++j) {
        usedLeft.lo[j] = minL[j];
        usedLeft.hi[j] = maxL[3 + j];
        usedRight.lo[j] = minR[j];
        usedRight.hi[j] = maxR[3 + j];
      }
    }
#endif
    return {nl, nr};
  }

  // r := r ∩ box; false when that is empty.
  static bool intersect(Ref& r, const Aabb& box) {
    const float blo[3] = {box.lower.x, box.lower.y, box.lower.z};
    const float bhi[3] = {box.upper.x, box.upper.y, box.upper.z};
    bool nonEmpty = true;
    for (int k = 0; k < 3; ++k) {
      r.lo[k] = std::max(r.lo[k], blo[k]);
      r.hi[k] = std::min(r.hi[k], bhi[k]);
      nonEmpty &= r.lo[k] <= r.hi[k];
    }
    return nonEmpty;
  }
};

inline Children childCells(const Cell& cell, const Split& split) {
  Children c;
  c.left.box = c.right.box = cell.box;
  c.left.box.hi[split.axis] = split.pos;
  c.right.box.lo[split.axis] = split.pos;
  return c;
}

}  // namespace lancer::binned
