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

#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer::bvh {

namespace {

constexpr int kMaxBins = 32;
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
  F4 lo[3][kMaxBins], hi[3][kMaxBins];
  std::uint32_t triangles[3][kMaxBins];

  Bins(const PrimRef* refs, std::size_t begin, std::size_t end, const Grid& grid) {
    static_assert(offsetof(PrimRef, face) == 3 * sizeof(float) && offsetof(PrimRef, hi) == 4 * sizeof(float));
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < grid.bins; ++b) {
        lo[a][b] = F4::all(kInf);
        hi[a][b] = F4::all(-kInf);
        triangles[a][b] = 0;
      }
    }
    for (std::size_t i = begin; i < end; ++i) {
      const PrimRef& r = refs[i];
      const F4 rlo = F4::load(r.lo), rhi = F4::load(r.hi);
      alignas(16) int b[4];
      grid.bin(r, b);
      for (int a = 0; a < 3; ++a) {
        lo[a][b[a]] = min(lo[a][b[a]], rlo);
        hi[a][b[a]] = max(hi[a][b[a]], rhi);
        triangles[a][b[a]] += r.triangles;
      }
    }
  }
  // The union of bins [first, last) on `axis`.
  Box4 unite(int axis, int first, int last) const {
    Box4 out;
    for (int b = first; b < last; ++b) out.extend(lo[axis][b], hi[axis][b]);
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
  // by axis). Both sweeps grow the three axes' boxes at once and take their areas together.
  alignas(16) float rightArea[kMaxBins][4], leftArea[kMaxBins][4];
  std::uint32_t rightCount[3][kMaxBins], leftCount[3][kMaxBins];
  {
    F4 lo[3] = {F4::all(kInf), F4::all(kInf), F4::all(kInf)};
    F4 hi[3] = {F4::all(-kInf), F4::all(-kInf), F4::all(-kInf)};
    std::uint32_t triangles[3] = {0, 0, 0};
    for (int b = count - 1; b > 0; --b) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = min(lo[a], bins.lo[a][b]);
        hi[a] = max(hi[a], bins.hi[a][b]);
        rightCount[a][b] = triangles[a] += bins.triangles[a][b];
      }
      areasOf(lo, hi).store(rightArea[b]);
    }
  }
  {
    F4 lo[3] = {F4::all(kInf), F4::all(kInf), F4::all(kInf)};
    F4 hi[3] = {F4::all(-kInf), F4::all(-kInf), F4::all(-kInf)};
    std::uint32_t triangles[3] = {0, 0, 0};
    for (int b = 1; b < count; ++b) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = min(lo[a], bins.lo[a][b - 1]);
        hi[a] = max(hi[a], bins.hi[a][b - 1]);
        leftCount[a][b] = triangles[a] += bins.triangles[a][b - 1];
      }
      areasOf(lo, hi).store(leftArea[b]);
    }
  }
  float best = kInf;
  for (int a = 0; a < 3; ++a) {
    if (!grid.usable[a]) continue;
    for (int b = 1; b < count; ++b) {
      // An empty side's area is never read (its box's lanes are infinite).
      if (leftCount[a][b] == 0 || rightCount[a][b] == 0) continue;
      const float cost = leftArea[b][a] * float(leftCount[a][b]) + rightArea[b][a] * float(rightCount[a][b]);
      if (cost < best) {
        best = cost;
        split.axis = a;
        split.bin = b;
        split.leftTriangles = leftCount[a][b];
      }
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
    const Grid grid(range);
    const int axis = range.split.axis, bin = range.split.bin;
    auto goesLeft = [&](const PrimRef& r) {
      alignas(16) int b[4];
      grid.bin(r, b);
      return b[axis] < bin;
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
