#include "lancer/accel/bvh/build_parts.hpp"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <utility>

#ifdef __SSE2__
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

#include "lancer/accel/bvh/binning.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/isa.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer::bvh {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Four floats (x, y, z and a lane never read): a reference's corner, a box's corner, a bin index
// per axis. SSE where there is SSE; the same arithmetic lane by lane elsewhere.
#ifdef __SSE2__
struct F4 {
  __m128 v;
  static F4 load(const float* p) { return {_mm_loadu_ps(p)}; }
  static F4 set(float x, float y, float z) { return {_mm_setr_ps(x, y, z, 0.0f)}; }
  static F4 all(float x) { return {_mm_set1_ps(x)}; }
  friend F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
  friend F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
  friend F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
  friend F4 min(F4 a, F4 b) { return {_mm_min_ps(a.v, b.v)}; }
  friend F4 max(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
  void store(float* p) const { _mm_storeu_ps(p, v); }
  // Lanes truncated to integers.
  void truncate(int* out) const { _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_cvttps_epi32(v)); }
};
// Four 32-bit integers (a count per axis) and lane masks (all bits set where true), for the SAH
// sweep's three axes at once.
struct I4 {
  __m128i v;
  static I4 load(const std::uint32_t* p) { return {_mm_loadu_si128(reinterpret_cast<const __m128i*>(p))}; }
  static I4 all(std::uint32_t x) { return {_mm_set1_epi32(static_cast<int>(x))}; }
  friend I4 operator+(I4 a, I4 b) { return {_mm_add_epi32(a.v, b.v)}; }
  void store(std::uint32_t* p) const { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), v); }
  // The counts as floats (exact below 2^24; rounded as a conversion of each count alone above).
  F4 toFloat() const { return {_mm_cvtepi32_ps(v)}; }
  // Lanes not zero, as a mask.
  F4 nonZero() const {
    return {_mm_castsi128_ps(_mm_xor_si128(_mm_cmpeq_epi32(v, _mm_setzero_si128()), _mm_set1_epi32(-1)))};
  }
};
inline F4 operator&(F4 a, F4 b) { return {_mm_and_ps(a.v, b.v)}; }
inline F4 lessThan(F4 a, F4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline F4 select(F4 mask, F4 a, F4 b) {
  return {_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v))};
}
inline I4 select(F4 mask, I4 a, I4 b) {
  const __m128i m = _mm_castps_si128(mask.v);
  return {_mm_or_si128(_mm_and_si128(m, a.v), _mm_andnot_si128(m, b.v))};
}
inline F4 maskOf(bool x, bool y, bool z) {
  return {_mm_castsi128_ps(_mm_setr_epi32(-int(x), -int(y), -int(z), 0))};
}
#else
struct F4 {
  float v[4];
  static F4 load(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
  static F4 set(float x, float y, float z) { return {{x, y, z, 0.0f}}; }
  static F4 all(float x) { return {{x, x, x, x}}; }
  template <typename Op>
  static F4 each(F4 a, F4 b, Op op) {
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
  }
  friend F4 operator+(F4 a, F4 b) {
    return each(a, b, [](float x, float y) { return x + y; });
  }
  friend F4 operator-(F4 a, F4 b) {
    return each(a, b, [](float x, float y) { return x - y; });
  }
  friend F4 operator*(F4 a, F4 b) {
    return each(a, b, [](float x, float y) { return x * y; });
  }
  // As minps / maxps: the second operand when the comparison fails.
  friend F4 min(F4 a, F4 b) {
    return each(a, b, [](float x, float y) { return x < y ? x : y; });
  }
  friend F4 max(F4 a, F4 b) {
    return each(a, b, [](float x, float y) { return x > y ? x : y; });
  }
  void store(float* p) const { std::memcpy(p, v, sizeof v); }
  void truncate(int* out) const {
    for (int k = 0; k < 4; ++k) out[k] = static_cast<int>(v[k]);
  }
};
// Lane masks are F4s whose lanes are 1 (true) or 0 (false) here.
struct I4 {
  std::uint32_t v[4];
  static I4 load(const std::uint32_t* p) { return {{p[0], p[1], p[2], p[3]}}; }
  static I4 all(std::uint32_t x) { return {{x, x, x, x}}; }
  friend I4 operator+(I4 a, I4 b) {
    return {{a.v[0] + b.v[0], a.v[1] + b.v[1], a.v[2] + b.v[2], a.v[3] + b.v[3]}};
  }
  void store(std::uint32_t* p) const { std::memcpy(p, v, sizeof v); }
  F4 toFloat() const {
    return {{float(std::int32_t(v[0])), float(std::int32_t(v[1])), float(std::int32_t(v[2])),
             float(std::int32_t(v[3]))}};
  }
  F4 nonZero() const {
    return {{v[0] ? 1.0f : 0.0f, v[1] ? 1.0f : 0.0f, v[2] ? 1.0f : 0.0f, v[3] ? 1.0f : 0.0f}};
  }
};
inline F4 operator&(F4 a, F4 b) {
  return F4::each(a, b, [](float x, float y) { return x != 0.0f && y != 0.0f ? 1.0f : 0.0f; });
}
inline F4 lessThan(F4 a, F4 b) {
  return F4::each(a, b, [](float x, float y) { return x < y ? 1.0f : 0.0f; });
}
inline F4 select(F4 mask, F4 a, F4 b) {
  F4 out;
  for (int k = 0; k < 4; ++k) out.v[k] = mask.v[k] != 0.0f ? a.v[k] : b.v[k];
  return out;
}
inline I4 select(F4 mask, I4 a, I4 b) {
  I4 out;
  for (int k = 0; k < 4; ++k) out.v[k] = mask.v[k] != 0.0f ? a.v[k] : b.v[k];
  return out;
}
inline F4 maskOf(bool x, bool y, bool z) {
  return {{x ? 1.0f : 0.0f, y ? 1.0f : 0.0f, z ? 1.0f : 0.0f, 0.0f}};
}
#endif

// A box as two F4 corners, grown by references and other boxes.
struct Box4 {
  F4 lo = F4::all(kInf), hi = F4::all(-kInf);
  void extend(F4 l, F4 h) {
    lo = min(lo, l);
    hi = max(hi, h);
  }
  void extend(const Box4& b) { extend(b.lo, b.hi); }
  float area() const {
    alignas(16) float l[4], h[4];
    lo.store(l);
    hi.store(h);
    if (l[0] > h[0]) return 0.0f;
    const float x = h[0] - l[0], y = h[1] - l[1], z = h[2] - l[2];
    return 2.0f * (x * y + y * z + z * x);
  }
  Box box() const {
    alignas(16) float l[4], h[4];
    lo.store(l);
    hi.store(h);
    Box out;
    for (int a = 0; a < 3; ++a) {
      out.lo[a] = l[a];
      out.hi[a] = h[a];
    }
    return out;
  }
};

// The surface areas of three boxes (axis a's box lo[a], hi[a]) in lanes 0-2, as Box4::area computes
// each of a box that is not empty (x * y + y * z + z * x, doubled: the same floats).
F4 areasOf(const F4 (&lo)[3], const F4 (&hi)[3]) {
#ifdef __SSE2__
  __m128 x = (hi[0] - lo[0]).v, y = (hi[1] - lo[1]).v, z = (hi[2] - lo[2]).v, w = _mm_setzero_ps();
  _MM_TRANSPOSE4_PS(x, y, z, w);  // now x holds every box's x extent, y its y, z its z
  const F4 dx{x}, dy{y}, dz{z};
#else
  F4 dx, dy, dz;
  for (int a = 0; a < 3; ++a) {
    const F4 d = hi[a] - lo[a];
    dx.v[a] = d.v[0];
    dy.v[a] = d.v[1];
    dz.v[a] = d.v[2];
  }
  dx.v[3] = dy.v[3] = dz.v[3] = 0.0f;
#endif
  return F4::all(2.0f) * (dx * dy + dy * dz + dz * dx);
}

// The bins of each axis over a range's centroids; a range of few references gets as many bins as
// references (at least four): a bin per reference is all a small range can use, and the sweep
// over the bins is the fixed cost of every split.
struct Grid {
  int bins = kMaxBins;
  F4 origin = F4::all(0.0f), scale = F4::all(0.0f), last = F4::all(0.0f);
  bool usable[3] = {false, false, false};
  float axisScale[3] = {0.0f, 0.0f, 0.0f};

  explicit Grid(const Range& range) {
    bins = static_cast<int>(std::clamp<std::size_t>(range.count(), 4, kMaxBins));
    float s[3];
    for (int a = 0; a < 3; ++a) {
      const float extent = range.centroids.hi[a] - range.centroids.lo[a];
      usable[a] = extent > 0.0f && std::isfinite(extent);
      s[a] = usable[a] ? float(bins) * (1.0f - 1e-5f) / extent : 0.0f;
    }
    origin = F4::set(range.centroids.lo[0], range.centroids.lo[1], range.centroids.lo[2]);
    scale = F4::set(s[0], s[1], s[2]);
    std::copy(s, s + 3, axisScale);
    last = F4::all(float(bins - 1));
  }
  // The bin of a reference on each axis (its doubled centroid, clamped to the grid).
  void bin(const PrimRef& r, int* out) const {
    min(max((F4::load(r.lo) + F4::load(r.hi) - origin) * scale, F4::all(0.0f)), last).truncate(out);
  }
};

// Each axis's bins: the box and the triangles of the references whose centroid falls in each.
// Only the grid's bins are set up: a small range pays for few.
struct Bins {
  struct Entry {
    F4 lo, hi;
  };
  Entry box[3][kMaxBins];
  std::uint32_t triangles[kMaxBins][4];  // bin b's triangles on axis a at [b][a] (lane 3 unused)

  Bins(const PrimRef* refs, std::size_t begin, std::size_t end, const Grid& grid) {
    static_assert(offsetof(PrimRef, face) == 3 * sizeof(float) && offsetof(PrimRef, hi) == 4 * sizeof(float));
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < grid.bins; ++b) box[a][b] = {F4::all(kInf), F4::all(-kInf)};
    }
    for (int b = 0; b < grid.bins; ++b) I4::all(0).store(triangles[b]);
    BinGrid g;
    grid.origin.store(g.origin);
    grid.scale.store(g.scale);
    g.last = float(grid.bins - 1);
    // Entries are two F4s (32 bytes, lo then hi), as fillBins reads them.
    static_assert(sizeof(Entry) == 8 * sizeof(float));
    float* boxes = reinterpret_cast<float*>(&box[0][0]);
    std::uint32_t* counts = &triangles[0][0];
    isa::dispatch([&](auto isa) { fillBins<decltype(isa)>(refs, begin, end, g, boxes, counts); });
  }
  const F4& lo(int axis, int b) const { return box[axis][b].lo; }
  const F4& hi(int axis, int b) const { return box[axis][b].hi; }
  // The union of bins [first, last) on `axis`.
  Box4 unite(int axis, int first, int last) const {
    Box4 out;
    for (int b = first; b < last; ++b) out.extend(box[axis][b].lo, box[axis][b].hi);
    return out;
  }
};

}  // namespace

Range rangeOf(const PrimRef* refs, std::uint32_t begin, std::uint32_t end) {
  Range range;
  range.begin = begin;
  range.end = end;
  Box4 bounds, centroids;
  for (std::uint32_t i = begin; i < end; ++i) {
    const PrimRef& r = refs[i];
    const F4 lo = F4::load(r.lo), hi = F4::load(r.hi);
    bounds.extend(lo, hi);
    const F4 c = lo + hi;
    centroids.extend(c, c);
    range.triangles += r.triangles;
  }
  if (begin < end) {
    range.bounds = bounds.box();
    range.centroids = centroids.box();
  }
  return range;
}

Split chooseSplit(const PrimRef* refs, const Range& range, const BvhBuildOptions& options, LeafRule rule) {
  Split split;
  if (range.count() <= 1) return split;
  const Grid grid(range);
  const Bins bins(refs, range.begin, range.end, grid);
  const int count = grid.bins;
  // Cheapest boundary: the sum of each side's area times its triangles (the first of equal ones, axis
  // by axis). The right sweep grows the three axes' boxes at once and takes their areas together; the
  // left sweep does the same and costs each boundary on the three axes at once, keeping each axis's
  // cheapest (the first of equal ones), then the cheapest axis (the first of equal ones): the same
  // choice, from the same floats, as costing every boundary axis by axis.
  alignas(16) float rightArea[kMaxBins][4];
  alignas(16) std::uint32_t rightCount[kMaxBins][4];
  {
    F4 lo[3] = {F4::all(kInf), F4::all(kInf), F4::all(kInf)};
    F4 hi[3] = {F4::all(-kInf), F4::all(-kInf), F4::all(-kInf)};
    I4 triangles = I4::all(0);
    for (int b = count - 1; b > 0; --b) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = min(lo[a], bins.lo(a, b));
        hi[a] = max(hi[a], bins.hi(a, b));
      }
      triangles = triangles + I4::load(bins.triangles[b]);
      triangles.store(rightCount[b]);
      areasOf(lo, hi).store(rightArea[b]);
    }
  }
  F4 bestCost = F4::all(kInf);
  I4 bestBin = I4::all(0), bestLeft = I4::all(0);
  {
    const F4 usable = maskOf(grid.usable[0], grid.usable[1], grid.usable[2]);
    F4 lo[3] = {F4::all(kInf), F4::all(kInf), F4::all(kInf)};
    F4 hi[3] = {F4::all(-kInf), F4::all(-kInf), F4::all(-kInf)};
    I4 triangles = I4::all(0);
    for (int b = 1; b < count; ++b) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = min(lo[a], bins.lo(a, b - 1));
        hi[a] = max(hi[a], bins.hi(a, b - 1));
      }
      triangles = triangles + I4::load(bins.triangles[b - 1]);
      const I4 right = I4::load(rightCount[b]);
      const F4 cost = areasOf(lo, hi) * triangles.toFloat() + F4::load(rightArea[b]) * right.toFloat();
      // An empty side's area is never used (its box's lanes are infinite).
      const F4 better = usable & triangles.nonZero() & right.nonZero() & lessThan(cost, bestCost);
      bestCost = select(better, cost, bestCost);
      bestBin = select(better, I4::all(static_cast<std::uint32_t>(b)), bestBin);
      bestLeft = select(better, triangles, bestLeft);
    }
  }
  alignas(16) float laneCost[4];
  alignas(16) std::uint32_t laneBin[4], laneLeft[4];
  bestCost.store(laneCost);
  bestBin.store(laneBin);
  bestLeft.store(laneLeft);
  float best = kInf;
  for (int a = 0; a < 3; ++a) {
    if (laneCost[a] < best) {
      best = laneCost[a];
      split.axis = a;
      split.bin = static_cast<int>(laneBin[a]);
      split.leftTriangles = laneLeft[a];
    }
  }
  const float area = range.bounds.area();
  const float leafCost = options.intersectionCost * float(range.triangles);
  const bool binned = best < kInf;
  split.cost =
      options.traversalCost + (area > 0.0f && binned ? options.intersectionCost * best / area : leafCost);
  const bool leafAllowed =
      rule == LeafRule::BySah ? range.triangles <= BvhNode::kMaxLeafTriangles : range.count() <= 1;
  if (leafAllowed && (rule == LeafRule::SingleReference || !binned || leafCost <= split.cost)) return split;
  split.kind = binned && range.depth < kMaxBinnedDepth ? SplitKind::Binned : SplitKind::Median;
  if (split.kind == SplitKind::Binned) {
    // Both sides' boxes from the bins: the partition need not gather them again.
    split.bins = count;
    split.origin = range.centroids.lo[split.axis];
    split.scale = grid.axisScale[split.axis];
    split.lastBin = float(count - 1);
    split.left = bins.unite(split.axis, 0, split.bin).box();
    split.right = bins.unite(split.axis, split.bin, count).box();
  }
  return split;
}

void partition(PrimRef* refs, const Range& range, Range& left, Range& right) {
  if (range.split.kind != SplitKind::Binned) {
    const std::uint32_t middle = range.begin + static_cast<std::uint32_t>(range.count() / 2);
    left = rangeOf(refs, range.begin, middle);
    right = rangeOf(refs, middle, range.end);
  } else {
    // Hoare's partition; each side's centroid box gathered as references are placed (their boxes
    // and triangles come from the bins).
    // A reference's bin on the split's axis, as Grid::bin finds it lane by lane (maxps, minps and a
    // truncation: the same floats).
    const int axis = range.split.axis, bin = range.split.bin;
    const float origin = range.split.origin, scale = range.split.scale, last = range.split.lastBin;
    auto goesLeft = [&](const PrimRef& r) {
      float x = (r.lo[axis] + r.hi[axis] - origin) * scale;
      x = x > 0.0f ? x : 0.0f;
      x = x < last ? x : last;
      return static_cast<int>(x) < bin;
    };
    left = Range{};
    right = Range{};
    Box4 leftCentroids, rightCentroids;
    auto add = [](Box4& side, const PrimRef& r) {
      const F4 c = F4::load(r.lo) + F4::load(r.hi);
      side.extend(c, c);
    };
    PrimRef* i = refs + range.begin;
    PrimRef* j = refs + range.end;
    while (true) {
      while (i < j && goesLeft(*i)) add(leftCentroids, *i++);
      while (i < j && !goesLeft(*(j - 1))) add(rightCentroids, *--j);
      if (i >= j) break;
      std::swap(*i, *--j);
      add(leftCentroids, *i++);
      add(rightCentroids, *j);
    }
    const auto middle = static_cast<std::uint32_t>(i - refs);
    left.begin = range.begin;
    left.end = right.begin = middle;
    right.end = range.end;
    left.bounds = range.split.left;
    right.bounds = range.split.right;
    left.centroids = leftCentroids.box();
    right.centroids = rightCentroids.box();
    left.triangles = range.split.leftTriangles;
    right.triangles = range.triangles - left.triangles;
  }
  left.firstTriangle = range.firstTriangle;
  right.firstTriangle = range.firstTriangle + left.triangles;
  left.depth = right.depth = range.depth + 1;
}

bool isSliverFace(std::span<const Vec3> positions, const MeshFace& face) {
  const Vec3& a = positions[face.vertex[0]];
  if (isSliverTriangle(a, positions[face.vertex[1]], positions[face.vertex[2]])) return true;
  return face.isQuad() && isSliverTriangle(a, positions[face.vertex[2]], positions[face.vertex[3]]);
}

PrimRef faceReference(std::span<const Vec3> positions, const MeshFace& face, std::uint32_t id) {
  PrimRef r;
  r.face = id;
  r.triangles = face.isQuad() ? 2 : 1;
  for (int a = 0; a < 3; ++a) {
    // + 0.0f turns -0 into +0, so equal positions compare (and bin) alike.
    r.lo[a] = r.hi[a] = positions[face.vertex[0]][a] + 0.0f;
    for (int k = 1; k < face.cornerCount(); ++k) {
      const float p = positions[face.vertex[k]][a] + 0.0f;
      r.lo[a] = std::min(r.lo[a], p);
      r.hi[a] = std::max(r.hi[a], p);
    }
  }
  return r;
}

void gatherSlivers(std::span<const Vec3> positions, const MeshFace& face, std::uint32_t id,
                   PackedTriangle* out) {
  const Vec3& a = positions[face.vertex[0]];
  out[0] = {a, positions[face.vertex[1]], positions[face.vertex[2]], id};
  if (face.isQuad()) out[1] = {a, positions[face.vertex[2]], positions[face.vertex[3]], id};
}

GatheredFaces gatherFaces(std::span<const Vec3> positions, std::span<const MeshFace> faces, int threads) {
  auto isSliver = [&](const MeshFace& face) { return isSliverFace(positions, face); };
  // A first pass counts each chunk's tree faces and sliver triangles, a second writes them where the
  // counts before them put them, in face order.
  const ChunkPlan plan(faces.size(), 1 << 14);
  std::vector<std::size_t> kept(plan.chunks + 1, 0), dropped(plan.chunks + 1, 0);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = 0, slivers = 0;
    for (std::size_t f = begin; f < end; ++f) {
      if (isSliver(faces[f])) {
        slivers += faces[f].isQuad() ? 2 : 1;
      } else {
        ++tree;
      }
    }
    kept[chunk + 1] = tree;
    dropped[chunk + 1] = slivers;
  });
  for (std::size_t c = 0; c < plan.chunks; ++c) {
    kept[c + 1] += kept[c];
    dropped[c + 1] += dropped[c];
  }
  GatheredFaces out;
  out.refs = vectorOnHugePages<PrimRef>(kept.back());
  out.slivers.resize(dropped.back());
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = kept[chunk], sliver = dropped[chunk];
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = faces[f];
      const auto id = static_cast<std::uint32_t>(f);
      if (isSliver(face)) {
        gatherSlivers(positions, face, id, out.slivers.data() + sliver);
        sliver += face.isQuad() ? 2 : 1;
        continue;
      }
      out.refs[tree++] = faceReference(positions, face, id);
    }
  });
  return out;
}

}  // namespace lancer::bvh
