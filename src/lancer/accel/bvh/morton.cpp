#include "lancer/accel/bvh/morton.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer::bvh {

namespace {

constexpr int kBitsPerAxis = 10;
constexpr int kDigitBits = 10;  // three passes of the radix sort over the 30-bit code
constexpr std::size_t kDigits = std::size_t(1) << kDigitBits;

// x's low 10 bits spread to every third bit.
std::uint32_t spread(std::uint32_t x) {
  x &= 0x3FFu;
  x = (x | (x << 16)) & 0x030000FFu;
  x = (x | (x << 8)) & 0x0300F00Fu;
  x = (x | (x << 4)) & 0x030C30C3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

// The centroids' box (doubled centroids, as the build bins them).
Box centroidBox(const std::vector<PrimRef>& refs, int threads) {
  const ChunkPlan plan(refs.size(), 1 << 15);
  std::vector<Box> boxes(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    Box box;
    for (std::size_t i = begin; i < end; ++i) {
      const PrimRef& r = refs[i];
      const float c[3] = {r.lo[0] + r.hi[0], r.lo[1] + r.hi[1], r.lo[2] + r.hi[2]};
      box.extend(c, c);
    }
    boxes[chunk] = box;
  });
  Box all;
  for (const Box& box : boxes) all.extend(box);
  return all;
}

// Morton codes of centroids over a box of (doubled) centroids.
struct MortonGrid {
  static constexpr float kCells = float(1u << kBitsPerAxis);
  float origin[3], scale[3];

  explicit MortonGrid(const Box& box) {
    for (int a = 0; a < 3; ++a) {
      const float extent = box.hi[a] - box.lo[a];
      origin[a] = box.lo[a];
      scale[a] = extent > 0.0f && std::isfinite(extent) ? kCells * (1.0f - 1e-5f) / extent : 0.0f;
    }
  }
  std::uint32_t code(const PrimRef& r) const {
    std::uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      float cell = (r.lo[a] + r.hi[a] - origin[a]) * scale[a];
      cell = cell > 0.0f ? std::min(cell, kCells - 1.0f) : 0.0f;  // NaN to 0 too
      code |= spread(static_cast<std::uint32_t>(cell)) << a;
    }
    return code;
  }
};

// Keys code << 32 | index sorted by code, stable: least significant digit first, each pass a
// histogram per chunk, the chunks' offsets in chunk order, and a scatter per chunk.
void radixSort(std::vector<std::uint64_t>& keys, int threads) {
  std::vector<std::uint64_t> other = vectorOnHugePages<std::uint64_t>(keys.size());
  const ChunkPlan plan(keys.size(), 1 << 15);
  std::vector<std::array<std::uint32_t, kDigits>> offsets(plan.chunks);
  for (int shift = 32; shift < 32 + 3 * kBitsPerAxis; shift += kDigitBits) {
    auto digit = [shift](std::uint64_t key) { return (key >> shift) & (kDigits - 1); };
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::array<std::uint32_t, kDigits>& count = offsets[chunk];
      count.fill(0);
      for (std::size_t i = begin; i < end; ++i) ++count[digit(keys[i])];
    });
    std::uint32_t sum = 0;
    for (std::size_t d = 0; d < kDigits; ++d) {
      for (std::size_t c = 0; c < plan.chunks; ++c) {
        const std::uint32_t count = offsets[c][d];
        offsets[c][d] = sum;
        sum += count;
      }
    }
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::array<std::uint32_t, kDigits>& next = offsets[chunk];
      for (std::size_t i = begin; i < end; ++i) other[next[digit(keys[i])]++] = keys[i];
    });
    keys.swap(other);
  }
}

// Cuts sorted keys [begin, end) at the highest bit where their codes differ until each piece holds
// at most `most` keys.
void cut(const std::vector<std::uint64_t>& keys, std::uint32_t begin, std::uint32_t end, std::uint32_t most,
         std::vector<Cluster>& out) {
  if (end - begin <= most) {
    out.push_back({begin, end});
    return;
  }
  const auto differ = static_cast<std::uint32_t>((keys[begin] ^ keys[end - 1]) >> 32);
  if (differ == 0) {
    for (std::uint32_t first = begin; first < end; first += most)
      out.push_back({first, std::min(end, first + most)});
    return;
  }
  const int bit = 31 - std::countl_zero(differ);
  const auto middle =
      std::partition_point(keys.begin() + begin, keys.begin() + end,
                           [bit](std::uint64_t key) { return ((key >> 32 >> bit) & 1u) == 0; });
  const auto split = static_cast<std::uint32_t>(middle - keys.begin());
  cut(keys, begin, split, most, out);
  cut(keys, split, end, most, out);
}

}  // namespace

std::vector<Cluster> mortonClusters(std::vector<PrimRef>& refs, std::uint32_t maxReferences, int threads) {
  std::vector<Cluster> clusters;
  const auto n = static_cast<std::uint32_t>(refs.size());
  if (n == 0) return clusters;
  const MortonGrid grid(centroidBox(refs, threads));
  std::vector<std::uint64_t> keys = vectorOnHugePages<std::uint64_t>(n);
  parallelFor(n, threads, 1 << 15,
              [&](std::size_t i) { keys[i] = std::uint64_t(grid.code(refs[i])) << 32 | i; });
  radixSort(keys, threads);
  {
    std::vector<PrimRef> sorted = vectorOnHugePages<PrimRef>(n);
    parallelFor(n, threads, 1 << 15, [&](std::size_t i) { sorted[i] = refs[keys[i] & 0xFFFFFFFFu]; });
    refs.swap(sorted);
  }
  cut(keys, 0, n, std::max<std::uint32_t>(1, maxReferences), clusters);
  return clusters;
}

MortonFaces gatherMortonFaces(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                              std::uint32_t maxReferences, int threads) {
  // A first pass counts each chunk's tree faces and sliver triangles and bounds the centroids; a
  // second writes the slivers and one key a tree face (its code, its face), in face order; the keys
  // sorted, the references are made in their order.
  const ChunkPlan plan(faces.size(), 1 << 14);
  std::vector<std::size_t> kept(plan.chunks + 1, 0), dropped(plan.chunks + 1, 0);
  std::vector<Box> boxes(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = 0, slivers = 0;
    Box box;
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = faces[f];
      if (isSliverFace(positions, face)) {
        slivers += face.isQuad() ? 2 : 1;
        continue;
      }
      ++tree;
      const PrimRef r = faceReference(positions, face, static_cast<std::uint32_t>(f));
      const float c[3] = {r.lo[0] + r.hi[0], r.lo[1] + r.hi[1], r.lo[2] + r.hi[2]};
      box.extend(c, c);
    }
    kept[chunk + 1] = tree;
    dropped[chunk + 1] = slivers;
    boxes[chunk] = box;
  });
  Box all;
  for (std::size_t c = 0; c < plan.chunks; ++c) {
    kept[c + 1] += kept[c];
    dropped[c + 1] += dropped[c];
    all.extend(boxes[c]);
  }
  const MortonGrid grid(all);
  MortonFaces out;
  out.slivers.resize(dropped.back());
  std::vector<std::uint64_t> keys = vectorOnHugePages<std::uint64_t>(kept.back());
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = kept[chunk], sliver = dropped[chunk];
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = faces[f];
      const auto id = static_cast<std::uint32_t>(f);
      if (isSliverFace(positions, face)) {
        gatherSlivers(positions, face, id, out.slivers.data() + sliver);
        sliver += face.isQuad() ? 2 : 1;
        continue;
      }
      keys[tree++] = std::uint64_t(grid.code(faceReference(positions, face, id))) << 32 | id;
    }
  });
  const auto n = static_cast<std::uint32_t>(keys.size());
  if (n == 0) return out;
  radixSort(keys, threads);
  out.refs = vectorOnHugePages<PrimRef>(n);
  parallelFor(n, threads, 1 << 15, [&](std::size_t i) {
    const auto id = static_cast<std::uint32_t>(keys[i] & 0xFFFFFFFFu);
    out.refs[i] = faceReference(positions, faces[id], id);
  });
  cut(keys, 0, n, std::max<std::uint32_t>(1, maxReferences), out.clusters);
  return out;
}

}  // namespace lancer::bvh
