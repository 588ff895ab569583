#include "lancer/accel/bvh/morton.hpp"

#include <algorithm>
#include <bit>

#include "lancer/util/huge_pages.hpp"
#include "lancer/util/morton_order.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer::bvh {

namespace {

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
  const Box box = centroidBox(refs, threads);
  const MortonGrid grid(box.lo, box.hi);
  std::vector<std::uint64_t> keys = vectorOnHugePages<std::uint64_t>(n);
  parallelFor(n, threads, 1 << 15, [&](std::size_t i) {
    const PrimRef& r = refs[i];
    const float centroid[3] = {r.lo[0] + r.hi[0], r.lo[1] + r.hi[1], r.lo[2] + r.hi[2]};
    keys[i] = std::uint64_t(grid.code(centroid)) << 32 | i;
  });
  sortMortonKeys(keys, threads);
  {
    std::vector<PrimRef> sorted = vectorOnHugePages<PrimRef>(n);
    parallelFor(n, threads, 1 << 15, [&](std::size_t i) { sorted[i] = refs[keys[i] & 0xFFFFFFFFu]; });
    refs.swap(sorted);
  }
  cut(keys, 0, n, std::max<std::uint32_t>(1, maxReferences), clusters);
  return clusters;
}

}  // namespace lancer::bvh
