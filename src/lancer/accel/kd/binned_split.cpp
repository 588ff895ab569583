#include "lancer/accel/kd/binned_split.hpp"

#include <algorithm>
#include <bit>
#include <span>

#include "lancer/accel/kd/window_sweep.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace lancer::binned {

namespace {

// The cell's geometry along one axis, for the SAH cost of a plane at p (Wald & Havran 2006, sec. 3).
struct AxisCost {
  float lo, hi, capArea, girth, invArea, kt, ki;
  AxisCost(const Box& cell, int axis, float invArea_, const KdBuildOptions& options)
      : lo(cell.lo[axis]),
        hi(cell.hi[axis]),
        invArea(invArea_),
        kt(options.traversalCost),
        ki(options.intersectionCost) {
    const float a = cell.hi[(axis + 1) % 3] - cell.lo[(axis + 1) % 3];
    const float b = cell.hi[(axis + 2) % 3] - cell.lo[(axis + 2) % 3];
    capArea = a * b;
    girth = a + b;
  }
  float sideArea(float length) const { return 2.0f * (capArea + length * girth) * invArea; }
  float operator()(float p, std::uint32_t nl, std::uint32_t nr) const {
    return kt + ki * (sideArea(p - lo) * float(nl) + sideArea(hi - p) * float(nr));
  }
};

}  // namespace

void BinCounts::count(const Ref* refs, std::size_t n, const BinGrid& grid, const Box& cell) {
  const int top = grid.bins - 1;
  std::uint32_t planar[6] = {0, 0, 0, 0, 0, 0};  // planarAtLo[0..2], planarAtHi[0..2]
#if defined(__AVX2__)
  // The six bounds of a reference are lanes 0-5 of one vector: one subtract, multiply and clamp
  // bins all six (the same operations, so the same bins, as BinGrid::binOf).
  const __m256 lo =
      _mm256_setr_ps(grid.lo[0], grid.lo[1], grid.lo[2], grid.lo[0], grid.lo[1], grid.lo[2], 0, 0);
  const __m256 scale = _mm256_setr_ps(grid.scale[0], grid.scale[1], grid.scale[2], grid.scale[0],
                                      grid.scale[1], grid.scale[2], 0, 0);
  const __m256 faces =
      _mm256_setr_ps(cell.lo[0], cell.lo[1], cell.lo[2], cell.hi[0], cell.hi[1], cell.hi[2], 0, 0);
  const __m256i zero = _mm256_setzero_si256(), last = _mm256_set1_epi32(top);
  const __m256i rowStart = _mm256_setr_epi32(0, bins, 2 * bins, 3 * bins, 4 * bins, 5 * bins, 0, 0);
  const __m256i swapHalves = _mm256_setr_epi32(3, 4, 5, 0, 1, 2, 6, 7);
  for (std::size_t i = 0; i < n; ++i) {
    if (i + 16 < n) _mm_prefetch(reinterpret_cast<const char*>(refs + i + 16), _MM_HINT_T0);
    const __m256 v = _mm256_load_ps(refs[i].lo);
    __m256i bin = _mm256_cvttps_epi32(_mm256_mul_ps(_mm256_sub_ps(v, lo), scale));
    bin = _mm256_add_epi32(_mm256_min_epi32(_mm256_max_epi32(bin, zero), last), rowStart);
    alignas(32) std::int32_t at[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(at), bin);
    for (int j = 0; j < 6; ++j) ++counts[at[j]];
    // Lane k < 3: lo == hi on axis k and lo on the cell's lower face; lane 3 + k: on the upper one.
    const __m256 flat = _mm256_cmp_ps(v, _mm256_permutevar8x32_ps(v, swapHalves), _CMP_EQ_OQ);
    const int mask = _mm256_movemask_ps(_mm256_and_ps(flat, _mm256_cmp_ps(v, faces, _CMP_EQ_OQ))) & 63;
    if (mask) {
      for (int j = 0; j < 6; ++j) planar[j] += (mask >> j) & 1;
    }
  }
#else
  float lo[6], scale[6];
  for (int k = 0; k < 3; ++k) {
    lo[k] = lo[k + 3] = grid.lo[k];
    scale[k] = scale[k + 3] = grid.scale[k];
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Ref& r = refs[i];
    const float* bound = r.lo;  // lo[3] then hi[3]
    for (int j = 0; j < 6; ++j) {
      const int bin = std::min(std::max(static_cast<int>((bound[j] - lo[j]) * scale[j]), 0), top);
      ++counts[j * bins + bin];
    }
    for (int k = 0; k < 3; ++k) {
      if (r.lo[k] == r.hi[k]) {
        planar[k] += r.lo[k] == cell.lo[k];
        planar[k + 3] += r.hi[k] == cell.hi[k];
      }
    }
  }
#endif
  for (int k = 0; k < 3; ++k) {
    planarAtLo[k] += planar[k];
    planarAtHi[k] += planar[k + 3];
  }
}

Split bestBinnedSplit(const BinCounts& counts, const BinGrid& grid, const Cell& cell, std::uint32_t n,
                      const KdBuildOptions& options) {
  Split best;
  const float area = cell.box.area();
  if (!(area > 0.0f)) return best;
  const float invArea = 1.0f / area;
  const float kt = options.traversalCost, ki = options.intersectionCost;
  auto consider = [&](int axis, float pos, bool planarLeft, float cost, int bin) {
    if (cost < best.cost) best = {axis, pos, planarLeft, cost, bin};
  };
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = cell.box.lo[axis], hi = cell.box.hi[axis];
    if (!(hi > lo)) continue;
    const AxisCost planeCost(cell.box, axis, invArea, options);
    const float flat = 2.0f * planeCost.capArea * invArea;
    if (const std::uint32_t planars = counts.planarAtLo[axis]; planars > 0) {
      const std::uint32_t rest = n - planars;
      const float c = kt + ki * (flat * float(planars) + float(rest));
      consider(axis, lo, true, rest > 0 ? c : c * options.emptySpaceFactor, -1);
    }
    if (const std::uint32_t planars = counts.planarAtHi[axis]; planars > 0) {
      const std::uint32_t rest = n - planars;
      const float c = kt + ki * (float(rest) + flat * float(planars));
      consider(axis, hi, false, rest > 0 ? c : c * options.emptySpaceFactor, -1);
    }
    const float usedLo = cell.used.lo[axis], usedHi = cell.used.hi[axis];
    const float minSlab = options.emptySpaceMinFraction * (hi - lo);
    if (usedLo - lo >= minSlab) {
      consider(axis, usedLo, false,
               (kt + ki * planeCost.sideArea(hi - usedLo) * float(n)) * options.emptySpaceFactor, -1);
    }
    if (hi - usedHi >= minSlab) {
      consider(axis, usedHi, true,
               (kt + ki * planeCost.sideArea(usedHi - lo) * float(n)) * options.emptySpaceFactor, -1);
    }
    if (grid.scale[axis] == 0.0f) continue;
    // Boundary b lies between bins b-1 and b: references starting below it reach the left, those
    // ending at or above it the right (exact up to where in its bin a bound falls).
    const float step = (usedHi - usedLo) / float(grid.bins);
    const std::uint32_t* starts = counts.row(axis);
    const std::uint32_t* ends = counts.row(axis + 3);
    std::uint32_t nl = 0, nr = n;
    float axisBest = best.cost;
    int axisBin = -1;
    for (int bin = 1; bin < grid.bins; ++bin) {
      nl += starts[bin - 1];
      nr -= ends[bin - 1];
      const float p = usedLo + step * float(bin);
      const float cost = planeCost(p, nl, nr);
      const bool better = p > lo && p < hi && cost < axisBest;
      axisBest = better ? cost : axisBest;
      axisBin = better ? bin : axisBin;
    }
    if (axisBin > 0) consider(axis, usedLo + step * float(axisBin), true, axisBest, axisBin);
  }
  return best;
}

std::size_t collectWindow(const Ref* refs, std::size_t n, const BinGrid& grid, int axis, int first, int last,
                          WindowEvent* events) {
  const float lo = grid.lo[axis], scale = grid.scale[axis];
  const int top = grid.bins - 1;
  const auto width = static_cast<unsigned>(last - first);
  auto inWindow = [&](float x) {
    const int bin = std::min(std::max(static_cast<int>((x - lo) * scale), 0), top);
    return static_cast<std::size_t>(static_cast<unsigned>(bin - first) <= width);
  };
  std::size_t m = 0;
  std::size_t i = 0;
#if defined(__AVX2__)
  // Eight references at a time: their bounds on the axis gathered, binned as binOf does, and only
  // those in the window written (in big cells, one bound in a hundred).
  const __m256i stride = _mm256_setr_epi32(0, 8, 16, 24, 32, 40, 48, 56);  // floats between refs
  const __m256 vLo = _mm256_set1_ps(lo), vScale = _mm256_set1_ps(scale);
  const __m256i zero = _mm256_setzero_si256(), vTop = _mm256_set1_epi32(top);
  const __m256i vFirst = _mm256_set1_epi32(first), vLast = _mm256_set1_epi32(last);
  auto inside = [&](__m256 x) {
    __m256i bin = _mm256_cvttps_epi32(_mm256_mul_ps(_mm256_sub_ps(x, vLo), vScale));
    bin = _mm256_min_epi32(_mm256_max_epi32(bin, zero), vTop);
    const __m256i below = _mm256_cmpgt_epi32(vFirst, bin), above = _mm256_cmpgt_epi32(bin, vLast);
    return ~_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(below, above))) & 0xFF;
  };
  for (; i + 8 <= n; i += 8) {
    const float* base = refs[i].lo + axis;
    const __m256 a = _mm256_i32gather_ps(base, stride, 4);
    const __m256 b = _mm256_i32gather_ps(base + 3, stride, 4);
    const int planar = _mm256_movemask_ps(_mm256_cmp_ps(a, b, _CMP_EQ_OQ));
    const int keepA = inside(a), keepB = inside(b) & ~planar;
    if ((keepA | keepB) == 0) continue;
    // In reference order, lower bound before upper: the order of the scalar loop below.
    for (int lane = 0; lane < 8; ++lane) {
      const Ref& r = refs[i + std::size_t(lane)];
      if ((keepA >> lane) & 1) events[m++] = {r.lo[axis], (planar >> lane) & 1 ? 1 : 2};
      if ((keepB >> lane) & 1) events[m++] = {r.hi[axis], 0};
    }
  }
#endif
  // Branch-free (whether a bound is in the window is a coin toss in small cells): each bound is
  // written, and kept by the count of those in the window.
  for (; i < n; ++i) {
    const float a = refs[i].lo[axis], b = refs[i].hi[axis];
    const std::size_t planar = a == b;
    const std::size_t keepA = inWindow(a), keepB = inWindow(b) & (planar ^ 1);
    events[m] = {a, 2 - static_cast<int>(planar)};
    m += keepA;
    events[m] = {b, 0};
    m += keepB;
  }
  return m;
}

void refineInWindow(Split& best, const BinCounts& counts, const Cell& cell, std::uint32_t n,
                    WindowEvent* events, std::size_t eventCount, const KdBuildOptions& options) {
  const int axis = best.axis;
  const int first = std::max(best.bin - 1, 0);
  std::uint32_t nl = 0, nr = n;
  const std::uint32_t* starts = counts.row(axis);
  const std::uint32_t* ends = counts.row(axis + 3);
  for (int bin = 0; bin < first; ++bin) {
    nl += starts[bin];
    nr -= ends[bin];
  }
  // Sorted as integers: the position's bits mapped to an order-preserving key (-0 as +0), then
  // the type; about twice as fast as comparing the structs.
  static_assert(sizeof(WindowEvent) == sizeof(std::uint64_t));
  auto* keys = reinterpret_cast<std::uint64_t*>(events);
  for (std::size_t i = 0; i < eventCount; ++i) {
    const auto bits = std::bit_cast<std::uint32_t>(events[i].pos + 0.0f);
    const std::uint32_t ordered = (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
    keys[i] = std::uint64_t(ordered) << 32 | static_cast<std::uint32_t>(events[i].type);
  }
  std::sort(keys, keys + eventCount);
  for (std::size_t i = 0; i < eventCount; ++i) {
    const auto ordered = static_cast<std::uint32_t>(keys[i] >> 32);
    const std::uint32_t bits = (ordered & 0x80000000u) ? ordered & 0x7FFFFFFFu : ~ordered;
    const auto type = static_cast<int>(keys[i] & 0xFFFFFFFFu);
    events[i] = {std::bit_cast<float>(bits), type};
  }
  const AxisCost planeCost(cell.box, axis, 1.0f / cell.box.area(), options);
  sweepWindowEvents(std::span<const WindowEvent>(events, eventCount), planeCost, nl, nr,
                    [&](float p, bool planarsLeft, float cost) {
                      if (cost < best.cost) best = {axis, p, planarsLeft, cost, -1};
                    });
}

// Candidate planes of exactSmallSplit: each reference's lower and upper bound.
constexpr std::size_t kSmallCandidates = (2 * kSmallCell + 7) / 8 * 8;

#if defined(__AVX2__)

// One axis of exactSmallSplit: V vectors of 8 candidate planes, their counts kept in registers.
struct SmallAxis {
  const Ref* refs;
  std::size_t n;
  int axis;
  const float* candidate;
  float cellLo, cellHi, minSlab, invArea;
  const AxisCost& planeCost;
  const KdBuildOptions& options;

  // search<V> for the V at run time.
  template <bool kPlanars, int V = 1>
  void dispatch(std::size_t vectors, Split& best) const {
    if constexpr (V <= int(kSmallCandidates / 8)) {
      if (vectors == std::size_t(V)) return search<V, kPlanars>(best);
      dispatch<kPlanars, V + 1>(vectors, best);
    }
  }

  // kPlanars: whether any reference lies flat on this axis (else none lies in a plane).
  template <int V, bool kPlanars>
  void search(Split& best) const {
    static_assert(V >= 1 && V <= int(kSmallCandidates / 8));
    __m256 p[V];
    __m256i l[V], r[V], f[V];
    for (int v = 0; v < V; ++v) {
      p[v] = _mm256_load_ps(candidate + 8 * v);
      l[v] = r[v] = f[v] = _mm256_setzero_si256();
    }
    // For every candidate plane at once: references starting below it (l), ending above it (r),
    // lying in it (f); as the sweep counts them (left: lo < p, right: hi > p).
    for (std::size_t j = 0; j < n; ++j) {
      const float a = refs[j].lo[axis], b = refs[j].hi[axis];
      const __m256 lo = _mm256_set1_ps(a), hi = _mm256_set1_ps(b);
      const __m256 planar = _mm256_castsi256_ps(_mm256_set1_epi32(a == b ? -1 : 0));
      for (int v = 0; v < V; ++v) {
        l[v] = _mm256_sub_epi32(l[v], _mm256_castps_si256(_mm256_cmp_ps(lo, p[v], _CMP_LT_OQ)));
        r[v] = _mm256_sub_epi32(r[v], _mm256_castps_si256(_mm256_cmp_ps(hi, p[v], _CMP_GT_OQ)));
        if constexpr (kPlanars) {
          f[v] = _mm256_sub_epi32(
              f[v], _mm256_castps_si256(_mm256_and_ps(planar, _mm256_cmp_ps(lo, p[v], _CMP_EQ_OQ))));
        }
      }
    }
    // The costs of every plane with its planars on the left (a) and on the right (b), +inf where
    // the plane is not strictly inside the cell (or has no planars, for b).
    const __m256 inf = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    const __m256 vLo = _mm256_set1_ps(cellLo), vHi = _mm256_set1_ps(cellHi);
    const __m256 cap = _mm256_set1_ps(planeCost.capArea), girth = _mm256_set1_ps(planeCost.girth);
    const __m256 twiceInvArea = _mm256_set1_ps(2.0f * invArea);
    const __m256 vkt = _mm256_set1_ps(planeCost.kt), vki = _mm256_set1_ps(planeCost.ki);
    const __m256 bonus = _mm256_set1_ps(options.emptySpaceFactor), slab = _mm256_set1_ps(minSlab);
    const __m256i zero = _mm256_setzero_si256();
    __m256 costA[V], costB[V];
    __m256 least = inf;
    for (int v = 0; v < V; ++v) {
      const __m256 below = _mm256_sub_ps(p[v], vLo), above = _mm256_sub_ps(vHi, p[v]);
      const __m256 inside =
          _mm256_and_ps(_mm256_cmp_ps(p[v], vLo, _CMP_GT_OQ), _mm256_cmp_ps(p[v], vHi, _CMP_LT_OQ));
      const __m256 pl = _mm256_mul_ps(_mm256_add_ps(cap, _mm256_mul_ps(below, girth)), twiceInvArea);
      const __m256 pr = _mm256_mul_ps(_mm256_add_ps(cap, _mm256_mul_ps(above, girth)), twiceInvArea);
      const __m256 wideLeft = _mm256_cmp_ps(below, slab, _CMP_GE_OQ);
      const __m256 wideRight = _mm256_cmp_ps(above, slab, _CMP_GE_OQ);
      auto cost = [&](__m256i cl, __m256i cr) {
        const __m256 c =
            _mm256_add_ps(vkt, _mm256_mul_ps(vki, _mm256_add_ps(_mm256_mul_ps(pl, _mm256_cvtepi32_ps(cl)),
                                                                _mm256_mul_ps(pr, _mm256_cvtepi32_ps(cr)))));
        const __m256 empty =
            _mm256_or_ps(_mm256_and_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(cl, zero)), wideLeft),
                         _mm256_and_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(cr, zero)), wideRight));
        return _mm256_blendv_ps(c, _mm256_mul_ps(c, bonus), empty);
      };
      const __m256 hasPlanars = _mm256_castsi256_ps(_mm256_cmpgt_epi32(f[v], zero));
      costA[v] = _mm256_blendv_ps(inf, cost(_mm256_add_epi32(l[v], f[v]), r[v]), inside);
      costB[v] =
          _mm256_blendv_ps(inf, cost(l[v], _mm256_add_epi32(r[v], f[v])), _mm256_and_ps(inside, hasPlanars));
      least = _mm256_min_ps(least, _mm256_min_ps(costA[v], costB[v]));
    }
    __m128 m4 = _mm_min_ps(_mm256_castps256_ps128(least), _mm256_extractf128_ps(least, 1));
    m4 = _mm_min_ps(m4, _mm_movehl_ps(m4, m4));
    m4 = _mm_min_ss(m4, _mm_shuffle_ps(m4, m4, 1));
    const float m = _mm_cvtss_f32(m4);
    if (!(m < best.cost)) return;
    // The first candidate at that cost, planars left before right: the scalar order.
    const __m256 target = _mm256_set1_ps(m);
    for (int v = 0; v < V; ++v) {
      const int a = _mm256_movemask_ps(_mm256_cmp_ps(costA[v], target, _CMP_EQ_OQ));
      const int b = _mm256_movemask_ps(_mm256_cmp_ps(costB[v], target, _CMP_EQ_OQ));
      if ((a | b) == 0) continue;
      const int lane = __builtin_ctz(static_cast<unsigned>(a | b));
      const std::size_t c = 8 * std::size_t(v) + std::size_t(lane);
      const bool planarLeft = ((a >> lane) & 1) != 0;
      best = {axis, candidate[c], planarLeft, m, -1};
      return;
    }
  }
};
#endif

Split exactSmallSplit(const Ref* refs, std::size_t n, const Box& cell, const KdBuildOptions& options) {
  // Candidates: each reference's lower then upper bound (a planar one's twice: the same cost, so
  // the first wins, as if tried once), padded with +inf, which lies in no cell.
  constexpr std::size_t kCandidates = kSmallCandidates;
  Split best;
  const float area = cell.area();
  if (!(area > 0.0f) || n >= kSmallCell) return best;
  const float invArea = 1.0f / area;
  const float kt = options.traversalCost, ki = options.intersectionCost;
  const auto count = static_cast<std::uint32_t>(n);
  alignas(32) float candidate[kCandidates];
#if !defined(__AVX2__)
  std::int32_t nl[kCandidates], nr[kCandidates], np[kCandidates];
#endif
  for (int axis = 0; axis < 3; ++axis) {
    const float cellLo = cell.lo[axis], cellHi = cell.hi[axis];
    if (!(cellHi > cellLo)) continue;
    // Only planes strictly inside the cell are tried, and a planar reference's bound once: the
    // others could not be chosen (or would tie with an earlier candidate).
    std::uint32_t atLo = 0, atHi = 0, planars = 0;
    std::size_t candidates = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const float lo = refs[j].lo[axis], hi = refs[j].hi[axis];
      const bool planar = lo == hi;
      candidate[candidates] = lo;
      candidates += (lo > cellLo) & (lo < cellHi);
      candidate[candidates] = hi;
      candidates += (!planar) & (hi > cellLo) & (hi < cellHi);
      atLo += planar & (lo == cellLo);
      atHi += planar & (hi == cellHi);
      planars += planar;
    }
    const std::size_t used = (candidates + 7) / 8 * 8;
    for (std::size_t c = candidates; c < used; ++c) candidate[c] = std::numeric_limits<float>::infinity();
    const AxisCost planeCost(cell, axis, invArea, options);
    const float flat = 2.0f * planeCost.capArea * invArea;
    if (atLo > 0) {
      const float c = kt + ki * (flat * float(atLo) + float(count - atLo));
      const float cost = count > atLo ? c : c * options.emptySpaceFactor;
      if (cost < best.cost) best = {axis, cellLo, true, cost, -1};
    }
    if (atHi > 0) {
      const float c = kt + ki * (float(count - atHi) + flat * float(atHi));
      const float cost = count > atHi ? c : c * options.emptySpaceFactor;
      if (cost < best.cost) best = {axis, cellHi, false, cost, -1};
    }
    const float minSlab = options.emptySpaceMinFraction * (cellHi - cellLo);
    // For every candidate plane p at once: references starting below it (nl), ending above it
    // (nr), lying in it (np); as the sweep counts them (left: lo < p, right: hi > p).
#if defined(__AVX2__)
    const SmallAxis job{refs, n, axis, candidate, cellLo, cellHi, minSlab, invArea, planeCost, options};
    if (planars > 0)
      job.dispatch<true>(used / 8, best);
    else
      job.dispatch<false>(used / 8, best);
#else
    for (std::size_t c = 0; c < used; ++c) nl[c] = nr[c] = np[c] = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const float a = refs[j].lo[axis], b = refs[j].hi[axis];
      for (std::size_t c = 0; c < used; ++c) {
        nl[c] += a < candidate[c];
        nr[c] += b > candidate[c];
        np[c] += a == b && a == candidate[c];
      }
    }
    for (std::size_t c = 0; c < candidates; ++c) {
      const float p = candidate[c];
      if (!(p > cellLo && p < cellHi)) continue;
      const auto l = static_cast<std::uint32_t>(nl[c]), r = static_cast<std::uint32_t>(nr[c]);
      const auto f = static_cast<std::uint32_t>(np[c]);
      const bool wideLeft = p - cellLo >= minSlab, wideRight = cellHi - p >= minSlab;
      auto cost = [&](std::uint32_t cl, std::uint32_t cr) {
        const float sum = planeCost(p, cl, cr);
        return ((cl == 0 && wideLeft) || (cr == 0 && wideRight)) ? sum * options.emptySpaceFactor : sum;
      };
      const float planarLeftCost = cost(l + f, r);
      if (planarLeftCost < best.cost) best = {axis, p, true, planarLeftCost, -1};
      if (f > 0) {
        const float planarRightCost = cost(l, r + f);
        if (planarRightCost < best.cost) best = {axis, p, false, planarRightCost, -1};
      }
    }
#endif
  }
  return best;
}

Split splitFromBins(const BinCounts& counts, const BinGrid& grid, const Ref* refs, std::size_t n,
                    const Cell& cell, const KdBuildOptions& options, WindowRoom& window) {
  const auto count = static_cast<std::uint32_t>(n);
  Split split = bestBinnedSplit(counts, grid, cell, count, options);
  if (split.bin > 0) {
    WindowEvent* events = window.forRefs(n);
    const std::size_t eventCount = collectWindow(refs, n, grid, split.axis, split.bin - 1, split.bin, events);
    refineInWindow(split, counts, cell, count, events, eventCount, options);
  }
  return split;
}

Split findSplit(const Ref* refs, std::size_t n, const Cell& cell, const KdBuildOptions& options,
                BinCounts& counts, WindowRoom& window) {
  if (n < kSmallCell) return exactSmallSplit(refs, n, cell.box, options);
  const BinGrid grid(cell, n);
  counts.clear(grid.bins);
  counts.count(refs, n, grid, cell.box);
  return splitFromBins(counts, grid, refs, n, cell, options, window);
}

}  // namespace lancer::binned
