#include "lancer/mesh/face_shells.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <utility>

#include "lancer/mesh/parity_disjoint_sets.hpp"
#include "lancer/mesh/vertex_corners.hpp"
#include "lancer/mesh/vertex_ranges.hpp"
#include "lancer/util/huge_page_array.hpp"
#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// Vertices per chunk of the parallel loops.
constexpr std::size_t kGrain = 16384;
// Faces per chunk of the shells' numbering.
constexpr std::size_t kFaceGrain = 65536;

// Every face's edges bucketed by their smaller vertex, in face order within a bucket: a counting sort
// (one pass to count, one to scatter, in face order, each shared out by vertex ranges:
// vertex_ranges.hpp). The same table for any thread count.
struct EdgeBuckets {
  HugePageArray<FaceEdge> edges;
  std::vector<std::uint32_t> start;  // vertex v's edges: [start[v], start[v + 1])
  std::size_t vertexCount() const { return start.size() - 1; }
};

EdgeBuckets bucketFaceEdges(std::span<const MeshFace> faces, int threads) {
  const std::size_t vertexCount = vertexCountOf(faces, threads);
  EdgeBuckets buckets;
  std::vector<std::uint32_t>& bucketStart = buckets.start;
  bucketStart.assign(vertexCount + 1, 0);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (const MeshFace& face : faces) {
      const int n = face.cornerCount();
      for (int c = 0; c < n; ++c) {
        const std::uint32_t lo = std::min(face.vertex[c], face.vertex[(c + 1) % n]);
        if (lo >= firstVertex && lo < endVertex) ++bucketStart[lo + 1];
      }
    }
  });
  for (std::size_t v = 0; v < vertexCount; ++v) bucketStart[v + 1] += bucketStart[v];
  // 24 bytes per face, every one written below: no value-initialising pass before.
  buckets.edges = HugePageArray<FaceEdge>(bucketStart.back());
  FaceEdge* edges = buckets.edges.data();
  std::vector<std::uint32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
  forEachVertexRange(vertexCount, threads, [&](std::size_t firstVertex, std::size_t endVertex) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const MeshFace& face = faces[f];
      const int n = face.cornerCount();
      for (int c = 0; c < n; ++c) {
        const std::uint32_t a = face.vertex[c];
        const std::uint32_t b = face.vertex[(c + 1) % n];
        const std::uint32_t lo = std::min(a, b);
        if (lo >= firstVertex && lo < endVertex)
          edges[fill[lo]++] = {std::max(a, b), static_cast<std::uint32_t>(f) << 1 | (a < b ? 1u : 0u)};
      }
    }
  });
  return buckets;
}

// Each bucket ordered by larger vertex, equal ones in face order: then the table is grouped by edge,
// in (smaller, larger) order, as a stable sort of every edge by both would leave it. A vertex has a handful
// of edges (insertion sort); a fan centre with hundreds takes the library's stable sort. Two passes over the
// edges in all where a radix sort on the 64-bit key took eight (Manifold pairs its half-edges the same way).
void sortBuckets(EdgeBuckets& buckets, int threads) {
  parallelFor(buckets.vertexCount(), threads, kGrain, [&](std::size_t v) {
    FaceEdge* first = buckets.edges.data() + buckets.start[v];
    FaceEdge* last = buckets.edges.data() + buckets.start[v + 1];
    if (last - first > 32) {
      std::stable_sort(first, last);
      return;
    }
    for (FaceEdge* i = first + 1; i < last; ++i) {
      const FaceEdge e = *i;
      FaceEdge* j = i;
      for (; j > first && e.larger < (j - 1)->larger; --j) *j = *(j - 1);
      *j = e;
    }
  });
}

// Union-find over faces that several threads join at once (lock-free: a root is linked below a
// smaller root by compare-and-swap, retried when another thread linked it first; finds halve their
// paths). Each parent is at most its element, so a set's root is its smallest face, as in
// ParityDisjointSets: the sets, and so the shells, do not depend on the order of the unions.
class ConcurrentDisjointSets {
 public:
  explicit ConcurrentDisjointSets(std::size_t count) : parent_(count) {}
  // Each chunk of elements its own sets (the first touch of the array, on every thread).
  void reset(std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) parent_[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    for (;;) {
      const std::uint32_t up = load(x);
      if (up == x) return x;
      const std::uint32_t upper = load(up);
      // Halving: x skips to its grandparent (a failed exchange means another thread moved it).
      if (upper != up) {
        std::uint32_t expected = up;
        ref(x).compare_exchange_weak(expected, upper, std::memory_order_relaxed);
      }
      x = upper;
    }
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    for (;;) {
      a = find(a), b = find(b);
      if (a == b) return;
      if (a > b) std::swap(a, b);
      std::uint32_t expected = b;
      if (ref(b).compare_exchange_strong(expected, a, std::memory_order_acq_rel)) return;
    }
  }
  // Once the unions are over: x pointed straight at its root (atomically: other threads' finds may
  // be reading x's parent at the time).
  std::uint32_t flatten(std::uint32_t x) {
    const std::uint32_t root = find(x);
    ref(x).store(root, std::memory_order_relaxed);
    return root;
  }
  std::uint32_t parent(std::uint32_t x) const { return parent_[x]; }

 private:
  std::atomic_ref<std::uint32_t> ref(std::uint32_t x) { return std::atomic_ref<std::uint32_t>(parent_[x]); }
  std::uint32_t load(std::uint32_t x) { return ref(x).load(std::memory_order_acquire); }
  HugePageArray<std::uint32_t> parent_;
};

// The common case, a closed surface already wound consistently (the mesher's output: every edge
// shared by exactly two faces that traverse it in opposite directions): then every parity
// constraint says "turn both the same way", no set is broken and every flip bit is 0, and the
// shells are the connected components, found here on every thread at once, straight from the
// unsorted buckets (a bucket's two edges of one key found by comparing its few edges pairwise).
// Returns false, with `result` untouched, as soon as an edge says otherwise (findFaceShells then
// sorts the buckets and takes the one-thread parity walk); the same shells as that walk otherwise.
bool findConsistentShells(std::size_t faceCount, EdgeBuckets& buckets, int threads, FaceShells& result) {
  ConcurrentDisjointSets sets(faceCount);
  parallelChunks(ChunkPlan(faceCount, kFaceGrain), threads,
                 [&](std::size_t, std::size_t begin, std::size_t end) { sets.reset(begin, end); });
  std::atomic<bool> irregular{false};
  // The edges of one bucket, [first, last), in any order: each key on exactly two of them, one each
  // way. Bit i of `paired`: edge i found its partner already.
  auto pairBucket = [&](FaceEdge* first, FaceEdge* last) {
    const auto count = static_cast<std::size_t>(last - first);
    std::uint32_t paired = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (paired >> i & 1u) continue;
      std::size_t partner = count;
      for (std::size_t j = i + 1; j < count; ++j) {
        if (first[j].larger != first[i].larger) continue;
        if (partner != count) return false;  // three or more faces on the edge
        partner = j;
      }
      if (partner == count || first[partner].forward() == first[i].forward()) return false;
      paired |= 1u << partner;
      if (first[i].face() != first[partner].face()) sets.unite(first[i].face(), first[partner].face());
    }
    return true;
  };
  parallelChunks(ChunkPlan(buckets.vertexCount(), kGrain), threads,
                 [&](std::size_t, std::size_t begin, std::size_t end) {
                   for (std::size_t v = begin; v < end; ++v) {
                     if (irregular.load(std::memory_order_relaxed)) return;
                     FaceEdge* first = buckets.edges.data() + buckets.start[v];
                     FaceEdge* last = buckets.edges.data() + buckets.start[v + 1];
                     if (last - first > 32) {  // a fan centre: sorted, its pairs side by side
                       std::stable_sort(first, last);
                       for (FaceEdge* e = first; e < last; e += 2)
                         if (!pairBucket(e, std::min(e + 2, last))) {
                           irregular = true;
                           return;
                         }
                     } else if (!pairBucket(first, last)) {
                       irregular = true;
                       return;
                     }
                   }
                 });
  if (irregular) return false;
  // Shells numbered in order of their first face, their root: each chunk counts its roots, then
  // numbers them from its offset, then its other faces take their root's number.
  const ChunkPlan plan(faceCount, kFaceGrain);
  std::vector<std::uint32_t> chunkRoots(plan.chunks + 1, 0);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::uint32_t roots = 0;
    for (std::size_t f = begin; f < end; ++f) roots += sets.flatten(static_cast<std::uint32_t>(f)) == f;
    chunkRoots[chunk + 1] = roots;
  });
  for (std::size_t k = 0; k < plan.chunks; ++k) chunkRoots[k + 1] += chunkRoots[k];
  result.shellOfFace.resize(faceCount);
  parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::uint32_t next = chunkRoots[chunk];
    for (std::size_t f = begin; f < end; ++f)
      if (sets.parent(static_cast<std::uint32_t>(f)) == f) result.shellOfFace[f] = next++;
  });
  parallelChunks(plan, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const std::uint32_t root = sets.parent(static_cast<std::uint32_t>(f));
      if (root != f) result.shellOfFace[f] = result.shellOfFace[root];
    }
  });
  const std::size_t shellCount = chunkRoots[plan.chunks];
  result.closed.assign(shellCount, 1);
  result.consistent.assign(shellCount, 1);
  result.orientable.assign(shellCount, 1);
  result.bordered.assign(shellCount, 0);
  result.branched.assign(shellCount, 0);
  result.flip.assign(faceCount, 0);
  return true;
}

}  // namespace

FaceShells findFaceShells(std::span<const MeshFace> faces, int threads) {
  FaceShells result;
  const std::size_t faceCount = faces.size();
  if (faceCount >= ParityDisjointSets::kMaxCount)
    throw std::length_error("findFaceShells: more than 2^31 faces in one mesh");
  EdgeBuckets buckets = bucketFaceEdges(faces, threads);
  if (findConsistentShells(faceCount, buckets, threads, result)) return result;  // no edge table kept
  sortBuckets(buckets, threads);
  result.edges = std::move(buckets.edges);
  result.edgeStart = std::move(buckets.start);

  // Faces sharing an edge belong to one shell; an edge decides closedness and orientation. Two
  // faces on a manifold edge that traverse it the same way must be turned opposite ways for the
  // shell to agree (one parity constraint); at other edges the shell is open and no such bit holds.
  const HugePageArray<FaceEdge>& edges = result.edges;
  ParityDisjointSets sets(faceCount);
  // Per face, what its edges told about its shell (one byte for the four, written rarely).
  enum : std::uint8_t { kOpen = 1, kMisoriented = 2, kBorder = 4, kBranch = 8 };
  std::vector<std::uint8_t> edgeFlags(faceCount, 0);
  for (std::size_t v = 0; v + 1 < result.edgeStart.size(); ++v) {
    const std::size_t bucketEnd = result.edgeStart[v + 1];
    for (std::size_t i = result.edgeStart[v]; i < bucketEnd;) {
      std::size_t j = i + 1;
      while (j < bucketEnd && edges[j].larger == edges[i].larger) ++j;
      const std::uint32_t face = edges[i].face();
      if (j - i == 2) {
        const bool sameDirection = edges[i].forward() == edges[i + 1].forward();
        if (face != edges[i + 1].face()) sets.unite(face, edges[i + 1].face(), sameDirection ? 1 : 0);
        if (sameDirection) edgeFlags[face] |= kMisoriented;
      } else {
        for (std::size_t k = i + 1; k < j; ++k) sets.uniteFree(face, edges[k].face());
        edgeFlags[face] |= j - i == 1 ? kOpen | kBorder : kOpen | kMisoriented | kBranch;
      }
      i = j;
    }
  }
  constexpr std::uint32_t kUnnumbered = 0xFFFFFFFFu;
  std::vector<std::uint32_t> shellOfRoot(faceCount, kUnnumbered);
  result.shellOfFace.resize(faceCount);
  result.flip.resize(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) {
    const auto [root, bit] = sets.find(static_cast<std::uint32_t>(f));
    std::uint32_t& shell = shellOfRoot[root];
    if (shell == kUnnumbered) {
      shell = static_cast<std::uint32_t>(result.closed.size());
      result.closed.push_back(1);
      result.consistent.push_back(1);
      result.orientable.push_back(sets.broken(root) ? 0 : 1);
      result.bordered.push_back(0);
      result.branched.push_back(0);
    }
    result.shellOfFace[f] = shell;
    result.flip[f] = bit;
    if (const std::uint8_t flags = edgeFlags[f]; flags != 0) {
      if (flags & kOpen) result.closed[shell] = 0;
      if (flags & kMisoriented) result.consistent[shell] = 0;
      if (flags & kBorder) result.bordered[shell] = 1;
      if (flags & kBranch) result.branched[shell] = 1;
    }
  }
  return result;
}

}  // namespace lancer
