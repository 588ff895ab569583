#include "lancer/accel/bvh/morton.hpp"

#include <algorithm>
#include <bit>

#include "lancer/util/huge_page_array.hpp"
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
void cut(const std::uint64_t* keys, std::uint32_t begin, std::uint32_t end, std::uint32_t most,
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
  const std::uint64_t* middle = std::partition_point(
      keys + begin, keys + end, [bit](std::uint64_t key) { return ((key >> 32 >> bit) & 1u) == 0; });
  const auto split = static_cast<std::uint32_t>(middle - keys);
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
  cut(keys.data(), 0, n, std::max<std::uint32_t>(1, maxReferences), clusters);
  return clusters;
}

MortonFaces gatherMortonFaces(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                              std::uint32_t maxReferences, int threads) {
  // A first pass counts each chunk's tree faces and sliver triangles and bounds the centroids; a
  // second writes the slivers and one key a tree face (its code, its face), in face order; the keys
  // sorted, the references are made in their order.
  // The first pass also keeps a bit a face, set for a sliver face, so that the second does not test
  // again (each chunk its own words: none is shared between threads).
  const ChunkPlan plan(faces.size(), 1 << 14);
  std::vector<std::size_t> kept(plan.chunks + 1, 0), dropped(plan.chunks + 1, 0);
  std::vector<Box> boxes(plan.chunks);
  std::vector<std::vector<std::uint64_t>> sliverBits(plan.chunks);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = 0, slivers = 0;
    Box box;
    std::vector<std::uint64_t>& bits = sliverBits[chunk];
    bits.assign((end - begin + 63) / 64, 0);
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = faces[f];
      if (isSliverFace(positions, face)) {
        bits[(f - begin) / 64] |= std::uint64_t(1) << ((f - begin) % 64);
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
  const MortonGrid grid(all.lo, all.hi);
  MortonFaces out;
  out.slivers.resize(dropped.back());
  const std::size_t n = kept.back();
  if (n == 0) {
    // Every face a sliver: only the slivers to write.
    parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
      std::size_t sliver = dropped[chunk];
      for (std::size_t f = begin; f < end; ++f) {
        gatherSlivers(positions, faces[f], static_cast<std::uint32_t>(f), out.slivers.data() + sliver);
        sliver += faces[f].isQuad() ? 2 : 1;
      }
    });
    return out;
  }
  // The keys and the sort's scratch unwritten until the passes below fill them, on every thread.
  HugePageArray<std::uint64_t> keys(n), scratch(n);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::size_t tree = kept[chunk], sliver = dropped[chunk];
    const std::vector<std::uint64_t>& bits = sliverBits[chunk];
    for (std::size_t f = begin; f < end; ++f) {
      const MeshFace& face = faces[f];
      const auto id = static_cast<std::uint32_t>(f);
      if ((bits[(f - begin) / 64] >> ((f - begin) % 64)) & 1u) {
        gatherSlivers(positions, face, id, out.slivers.data() + sliver);
        sliver += face.isQuad() ? 2 : 1;
        continue;
      }
      const PrimRef r = faceReference(positions, face, id);
      const float centroid[3] = {r.lo[0] + r.hi[0], r.lo[1] + r.hi[1], r.lo[2] + r.hi[2]};
      keys[tree++] = std::uint64_t(grid.code(centroid)) << 32 | id;
    }
  });
  const std::uint64_t* sorted = sortMortonKeys(keys.data(), scratch.data(), n, threads);
  (sorted == keys.data() ? scratch : keys).reset();
  cut(sorted, 0, static_cast<std::uint32_t>(n), std::max<std::uint32_t>(1, maxReferences), out.clusters);
  out.refs = HugePageArray<PrimRef>(n);
  parallelFor(n, threads, 1 << 15, [&](std::size_t i) {
    const auto id = static_cast<std::uint32_t>(sorted[i] & 0xFFFFFFFFu);
    out.refs[i] = faceReference(positions, faces[id], id);
  });
  return out;
}

}  // namespace lancer::bvh
