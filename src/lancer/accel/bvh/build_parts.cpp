#include "lancer/accel/bvh/build_parts.hpp"

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer::bvh {

namespace {

constexpr int kBins = 32;

// The bins of each axis over a range's centroids.
struct Grid {
  float origin[3] = {0, 0, 0};
  float scale[3] = {0, 0, 0};
  bool usable[3] = {false, false, false};

  explicit Grid(const Range& range) {
    for (int a = 0; a < 3; ++a) {
      const float extent = range.centroids.hi[a] - range.centroids.lo[a];
      usable[a] = extent > 0.0f && std::isfinite(extent);
      origin[a] = range.centroids.lo[a];
      scale[a] = usable[a] ? float(kBins) * (1.0f - 1e-5f) / extent : 0.0f;
    }
  }
  int bin(int axis, float centroid) const {
    const int b = static_cast<int>((centroid - origin[axis]) * scale[axis]);
    return std::clamp(b, 0, kBins - 1);
  }
};

// Each axis's bins: the box and the triangles of the references whose centroid falls in each.
struct Bins {
#ifdef __SSE2__
  // One SSE min and max per reference and axis (Embree's binner): lanes 0-2 the box, lane 3 unused
  // (it takes the face and triangle words along, never read). SSE2 only, which every x86-64 CPU
  // has, so the one build for every CPU (util/isa.hpp) keeps it.
  alignas(16) float lo[3][kBins][4];
  alignas(16) float hi[3][kBins][4];
  std::uint32_t triangles[3][kBins] = {};

  Bins() {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < kBins; ++b) {
        _mm_store_ps(lo[a][b], _mm_set1_ps(std::numeric_limits<float>::infinity()));
        _mm_store_ps(hi[a][b], _mm_set1_ps(-std::numeric_limits<float>::infinity()));
      }
    }
  }
  // std::clamp per lane, in SSE2 (SSE4.1's min and max of 32-bit integers, by compare and select).
  static __m128i clampBin(__m128i bin, __m128i first, __m128i last) {
    const __m128i above = _mm_cmpgt_epi32(bin, last);
    bin = _mm_or_si128(_mm_and_si128(above, last), _mm_andnot_si128(above, bin));
    const __m128i below = _mm_cmpgt_epi32(first, bin);
    return _mm_or_si128(_mm_and_si128(below, first), _mm_andnot_si128(below, bin));
  }
  void add(const PrimRef* refs, std::size_t begin, std::size_t end, const Grid& grid) {
    static_assert(offsetof(PrimRef, face) == 3 * sizeof(float) && offsetof(PrimRef, hi) == 4 * sizeof(float));
    const __m128 origin = _mm_setr_ps(grid.origin[0], grid.origin[1], grid.origin[2], 0.0f);
    const __m128 scale = _mm_setr_ps(grid.scale[0], grid.scale[1], grid.scale[2], 0.0f);
    const __m128i last = _mm_set1_epi32(kBins - 1), first = _mm_setzero_si128();
    for (std::size_t i = begin; i < end; ++i) {
      const PrimRef& r = refs[i];
      const __m128 rlo = _mm_loadu_ps(r.lo), rhi = _mm_loadu_ps(r.hi);
      // Grid::bin, three axes at once: the same subtraction, product and truncation.
      const __m128i bin = clampBin(
          _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(_mm_add_ps(rlo, rhi), origin), scale)), first, last);
      alignas(16) int b[4];
      _mm_store_si128(reinterpret_cast<__m128i*>(b), bin);
      for (int a = 0; a < 3; ++a) {
        _mm_store_ps(lo[a][b[a]], _mm_min_ps(_mm_load_ps(lo[a][b[a]]), rlo));
        _mm_store_ps(hi[a][b[a]], _mm_max_ps(_mm_load_ps(hi[a][b[a]]), rhi));
        triangles[a][b[a]] += r.triangles;
      }
    }
  }
  void add(const Bins& other) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < kBins; ++b) {
        _mm_store_ps(lo[a][b], _mm_min_ps(_mm_load_ps(lo[a][b]), _mm_load_ps(other.lo[a][b])));
        _mm_store_ps(hi[a][b], _mm_max_ps(_mm_load_ps(hi[a][b]), _mm_load_ps(other.hi[a][b])));
        triangles[a][b] += other.triangles[a][b];
      }
    }
  }
  Box box(int a, int b) const {
    Box out;
    if (triangles[a][b] != 0) out.extend(lo[a][b], hi[a][b]);
    return out;
  }
#else
  Box boxes[3][kBins];
  std::uint32_t triangles[3][kBins] = {};

  void add(const PrimRef* refs, std::size_t begin, std::size_t end, const Grid& grid) {
    for (std::size_t i = begin; i < end; ++i) {
      const PrimRef& r = refs[i];
      for (int a = 0; a < 3; ++a) {
        const int b = grid.bin(a, r.lo[a] + r.hi[a]);
        boxes[a][b].extend(r.lo, r.hi);
        triangles[a][b] += r.triangles;
      }
    }
  }
  void add(const Bins& other) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < kBins; ++b) {
        boxes[a][b].extend(other.boxes[a][b]);
        triangles[a][b] += other.triangles[a][b];
      }
    }
  }
  Box box(int a, int b) const { return boxes[a][b]; }
#endif
};

}  // namespace

Range rangeOf(const PrimRef* refs, std::uint32_t begin, std::uint32_t end) {
  Range range;
  range.begin = begin;
  range.end = end;
  for (std::uint32_t i = begin; i < end; ++i) {
    const PrimRef& r = refs[i];
    range.bounds.extend(r.lo, r.hi);
    const float c[3] = {r.lo[0] + r.hi[0], r.lo[1] + r.hi[1], r.lo[2] + r.hi[2]};
    range.centroids.extend(c, c);
    range.triangles += r.triangles;
  }
  return range;
}

Split chooseSplit(const PrimRef* refs, const Range& range, const BvhBuildOptions& options, int threads) {
  Split split;
  if (range.count() <= 1) return split;
  const Grid grid(range);
  Bins bins;
  const ChunkPlan plan(range.count(), 1 << 14);
  if (threads > 1 && plan.chunks > 1) {
    std::vector<Bins> chunkBins(plan.chunks);
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      chunkBins[chunk].add(refs, range.begin + begin, range.begin + end, grid);
    });
    for (const Bins& part : chunkBins) bins.add(part);
  } else {
    bins.add(refs, range.begin, range.end, grid);
  }
  // Cheapest boundary: the sum of each side's area times its triangles (the first of equal ones).
  float best = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (!grid.usable[a]) continue;
    float rightArea[kBins];
    std::uint32_t rightCount[kBins];
    Box right;
    std::uint32_t count = 0;
    for (int b = kBins - 1; b > 0; --b) {
      right.extend(bins.box(a, b));
      count += bins.triangles[a][b];
      rightArea[b] = right.area();
      rightCount[b] = count;
    }
    Box left;
    count = 0;
    for (int b = 1; b < kBins; ++b) {
      left.extend(bins.box(a, b - 1));
      count += bins.triangles[a][b - 1];
      if (count == 0 || rightCount[b] == 0) continue;
      const float cost = left.area() * float(count) + rightArea[b] * float(rightCount[b]);
      if (cost < best) {
        best = cost;
        split.axis = a;
        split.bin = b;
      }
    }
  }
  const float area = range.bounds.area();
  const float leafCost = options.intersectionCost * float(range.triangles);
  const bool binned = best < std::numeric_limits<float>::infinity();
  split.cost =
      options.traversalCost + (area > 0.0f && binned ? options.intersectionCost * best / area : leafCost);
  if (range.triangles <= BvhNode::kMaxLeafTriangles && (!binned || leafCost <= split.cost)) return split;
  split.kind = binned && range.depth < kMaxBinnedDepth ? SplitKind::Binned : SplitKind::Median;
  return split;
}

void partition(PrimRef* refs, const Range& range, Range& left, Range& right) {
  if (range.split.kind != SplitKind::Binned) {
    const std::uint32_t middle = range.begin + static_cast<std::uint32_t>(range.count() / 2);
    left = rangeOf(refs, range.begin, middle);
    right = rangeOf(refs, middle, range.end);
  } else {
    // Hoare's partition, each reference added to its side's bounds as it is placed: one pass over
    // the references instead of a partition and a second pass for the bounds.
    const Grid grid(range);
    const int axis = range.split.axis, bin = range.split.bin;
    auto goesLeft = [&](const PrimRef& r) { return grid.bin(axis, r.lo[axis] + r.hi[axis]) < bin; };
    auto add = [](Range& side, const PrimRef& r) {
      side.bounds.extend(r.lo, r.hi);
      const float c[3] = {r.lo[0] + r.hi[0], r.lo[1] + r.hi[1], r.lo[2] + r.hi[2]};
      side.centroids.extend(c, c);
      side.triangles += r.triangles;
    };
    left = Range{};
    right = Range{};
    PrimRef* i = refs + range.begin;
    PrimRef* j = refs + range.end;
    while (true) {
      while (i < j && goesLeft(*i)) add(left, *i++);
      while (i < j && !goesLeft(*(j - 1))) add(right, *--j);
      if (i >= j) break;
      std::swap(*i, *--j);
      add(left, *i++);
      add(right, *j);
    }
    const auto middle = static_cast<std::uint32_t>(i - refs);
    left.begin = range.begin;
    left.end = right.begin = middle;
    right.end = range.end;
  }
  left.depth = right.depth = range.depth + 1;
}

GatheredFaces gatherFaces(std::span<const Vec3> positions, std::span<const MeshFace> faces, int threads) {
  auto isSliverFace = [&](const MeshFace& face) {
    const Vec3& a = positions[face.vertex[0]];
    if (isSliverTriangle(a, positions[face.vertex[1]], positions[face.vertex[2]])) return true;
    return face.isQuad() && isSliverTriangle(a, positions[face.vertex[2]], positions[face.vertex[3]]);
  };
  // A first pass counts each chunk's tree faces and sliver triangles, a second writes them where the
  // counts before them put them, in face order.
  const ChunkPlan plan(faces.size(), 1 << 14);
  std::vector<std::size_t> kept(plan.chunks + 1, 0), dropped(plan.chunks + 1, 0);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = 0, slivers = 0;
    for (std::size_t f = begin; f < end; ++f) {
      if (isSliverFace(faces[f])) {
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
      if (isSliverFace(face)) {
        const Vec3& a = positions[face.vertex[0]];
        out.slivers[sliver++] = {a, positions[face.vertex[1]], positions[face.vertex[2]], id};
        if (face.isQuad())
          out.slivers[sliver++] = {a, positions[face.vertex[2]], positions[face.vertex[3]], id};
        continue;
      }
      PrimRef& r = out.refs[tree++];
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
    }
  });
  return out;
}

}  // namespace lancer::bvh
