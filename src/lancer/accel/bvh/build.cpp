// The BVH build, HLBVH's plan with SAH everywhere (Garanzha, Pantaleoni & McAllister 2011): the face
// references in Morton order, cut into clusters of at most kMaxClusterReferences nearby faces
// (bvh/morton.hpp); the top of the tree by binned SAH over the clusters (each a box weighted by its
// triangles), then every cluster's subtree by binned SAH over its faces (Wald 2007, "On fast
// construction of SAH-based bounding volume hierarchies"), the clusters on every thread. Binary
// splits are collapsed into 8-wide nodes as they are made (Embree's BVHBuilderBinnedSAH: a node's
// child of largest area is split until it has eight) and written straight into the final array:
// the top's nodes first, then each cluster's, depth first, clusters in Morton order. A quad is one
// reference, its two triangles kept together in one leaf. A cluster's triangles are gathered right
// after its build, while its references are in cache.
// Determinism: the Morton sort is stable and every split is serial within its range, so the tree and
// its layout depend on the faces alone; threads only change who builds which cluster (clusters are
// built in batches, each batch's nodes appended in cluster order).
#include <sys/mman.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "lancer/accel/bvh/build_parts.hpp"
#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/bvh/morton.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {

using namespace bvh;

namespace {

void setLane(BvhNode& node, int k, const Box& box) {
  for (int a = 0; a < 3; ++a) {
    node.lower[a][k] = box.lo[a];
    node.upper[a][k] = box.hi[a];
  }
}

// What a subtree adds to the statistics (summed in cluster order: the same on any thread count).
struct TreeCounts {
  std::uint64_t nodes = 0, leaves = 0, triangleReferences = 0, depth = 0;
  void add(const TreeCounts& other) {
    nodes += other.nodes;
    leaves += other.leaves;
    triangleReferences += other.triangleReferences;
    depth = std::max(depth, other.depth);
  }
};

// A cluster's place in the tree: where the top left it and what its build made.
struct ClusterSlot {
  Range range;                 // its references, bounds and first triangle
  std::uint32_t topDepth = 0;  // wide depth of the lane that holds it
  std::uint32_t topNode = 0;   // that lane's node and lane (the root's lane 0 when there is no top)
  int topLane = 0;
  std::uint32_t code = 0;  // its root: a leaf code, or its first node relative to `firstNode`
  std::uint32_t nodeCount = 0;
  std::size_t scratchStart = 0;  // where its nodes lie in its batch chunk's scratch
  std::uint32_t firstNode = 0;   // in the final array
  std::size_t leafStart = 0;     // where its leaves' words lie in the scratch (codes relative to it)
  std::size_t leafWords = 0;
  std::size_t firstLeafWord = 0;  // in the final array
  TreeCounts counts;
};

// A batch chunk's nodes and leaves, reused from batch to batch.
struct ClusterScratch {
  std::vector<BvhNode> nodes;
  std::vector<std::uint64_t> leaves;
};

// A leaf code moved by `offset` words (its first word is below kMaxFirst: the build checks the total).
std::uint32_t movedLeaf(std::uint32_t code, std::size_t offset) {
  return code + static_cast<std::uint32_t>(offset);
}

}  // namespace

struct BvhBuilder {
  BvhBuilder(std::span<const Vec3> positions, std::span<const MeshFace> faces, HugePageArray<PrimRef>& refs,
             const BvhBuildOptions& options, Bvh& bvh)
      : positions_(positions), faces_(faces), refs_(refs), options_(options), bvh_(bvh) {}

  // Up to eight children of a range decided to split: the child of largest area split until there
  // are eight or none can be.
  int collapse(PrimRef* refs, const Range& range, Range (&child)[BvhNode::kWidth], LeafRule rule) const {
    child[0] = range;
    int count = 1;
    while (count < BvhNode::kWidth) {
      int pick = -1;
      float largest = -1.0f;
      for (int k = 0; k < count; ++k) {
        const float area = child[k].bounds.area();
        if (child[k].split.kind != SplitKind::Leaf && area > largest) {
          largest = area;
          pick = k;
        }
      }
      if (pick < 0) break;
      Range left, right;
      partition(refs, child[pick], left, right);
      left.split = chooseSplit(refs, left, options_, rule);
      right.split = chooseSplit(refs, right, options_, rule);
      child[pick] = left;
      child[count++] = right;
    }
    return count;
  }

  // The top over the clusters (`top`: one reference per cluster, face = its index), depth first
  // into the final array; each lane holding a single cluster is recorded in its slot.
  std::uint32_t writeTop(std::vector<PrimRef>& top, const Range& range, std::uint32_t depth) {
    Range child[BvhNode::kWidth];
    const int count = collapse(top.data(), range, child, LeafRule::SingleReference);
    const auto index = static_cast<std::uint32_t>(bvh_.nodes_.size());
    bvh_.nodes_.emplace_back().clear();
    ++topCounts_.nodes;
    topCounts_.depth = std::max<std::uint64_t>(topCounts_.depth, depth);
    for (int k = 0; k < count; ++k) {
      setLane(bvh_.nodes_[index], k, child[k].bounds);
      if (child[k].split.kind == SplitKind::Leaf) {
        ClusterSlot& slot = slots_[top[child[k].begin].face];
        slot.range.depth = child[k].depth;
        slot.topDepth = depth + 1;
        slot.topNode = index;
        slot.topLane = k;
      } else {
        const std::uint32_t below = writeTop(top, child[k], depth + 1);
        bvh_.nodes_[index].child[k] = below;
      }
    }
    return index;
  }

  // A cluster's subtree into `scratch` (node indices relative to `first`, leaf words to `leafStart`),
  // depth first.
  std::uint32_t writeNode(const Range& range, ClusterScratch& scratch, std::size_t first,
                          std::size_t leafStart, std::uint64_t depth, TreeCounts& counts) const {
    std::vector<BvhNode>& out = scratch.nodes;
    Range child[BvhNode::kWidth];
    const int count = collapse(refs_.data(), range, child, LeafRule::BySah);
    const std::size_t index = out.size();
    out.emplace_back().clear();
    ++counts.nodes;
    counts.depth = std::max(counts.depth, depth);
    for (int k = 0; k < count; ++k) {
      setLane(out[index], k, child[k].bounds);
      std::uint32_t code;
      if (child[k].split.kind == SplitKind::Leaf) {
        code = leafOf(child[k], scratch.leaves, leafStart, counts);
      } else {
        code = writeNode(child[k], scratch, first, leafStart, depth + 1, counts);
      }
      out[index].child[k] = code;
    }
    return static_cast<std::uint32_t>(index - first);
  }

  // The leaf of `range`'s faces appended to `leaves` (bvh/leaf.hpp), while its references are in
  // cache; its code's first word relative to `leafStart`.
  std::uint32_t leafOf(const Range& range, std::vector<std::uint64_t>& leaves, std::size_t leafStart,
                       TreeCounts& counts) const {
    ++counts.nodes;
    ++counts.leaves;
    counts.triangleReferences += range.triangles;
    std::uint32_t face[BvhNode::kMaxLeafTriangles], vertexOf[3 * BvhNode::kMaxLeafTriangles];
    Vec3 position[3 * BvhNode::kMaxLeafTriangles];
    std::uint32_t count = 0;
    auto add = [&](std::uint32_t id, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      face[count] = id;
      const std::uint32_t corner[3] = {a, b, c};
      for (int k = 0; k < 3; ++k) {
        vertexOf[3 * count + k] = corner[k];
        position[3 * count + k] = positions_[corner[k]];
      }
      ++count;
    };
    for (std::uint32_t i = range.begin; i < range.end; ++i) {
      const PrimRef& r = refs_[i];
      const MeshFace& f = faces_[r.face];
      add(r.face, f.vertex[0], f.vertex[1], f.vertex[2]);
      if (f.isQuad()) add(r.face, f.vertex[0], f.vertex[2], f.vertex[3]);
    }
    std::uint8_t local[3 * BvhNode::kMaxLeafTriangles];
    const std::uint32_t vertexCount = numberLeafVertices(vertexOf, 3 * count, local);
    const std::size_t at = leaves.size();
    leaves.resize(at + BvhLeaf::words(count, vertexCount), 0);
    writeLeaf(leaves.data() + at, count, face, position, vertexCount, local);
    return BvhNode::leaf(
        static_cast<std::uint32_t>(std::min<std::size_t>(at - leafStart, BvhNode::kMaxFirst)), count);
  }

  // A cluster built into `scratch`: its nodes and its leaves.
  void buildCluster(ClusterSlot& slot, ClusterScratch& scratch) const {
    Range range = slot.range;
    range.split = chooseSplit(refs_.data(), range, options_, LeafRule::BySah);
    slot.scratchStart = scratch.nodes.size();
    slot.leafStart = scratch.leaves.size();
    if (range.split.kind == SplitKind::Leaf) {
      slot.code = leafOf(range, scratch.leaves, slot.leafStart, slot.counts);
    } else {
      slot.code = writeNode(range, scratch, slot.scratchStart, slot.leafStart, slot.topDepth, slot.counts);
    }
    slot.nodeCount = static_cast<std::uint32_t>(scratch.nodes.size() - slot.scratchStart);
    slot.leafWords = scratch.leaves.size() - slot.leafStart;
  }

  // Every cluster, in batches of consecutive clusters built on every thread, each batch's nodes then
  // appended to the final array in cluster order (a cluster's child indices moved to where its
  // nodes land). The scratch arrays are reused from batch to batch, so little fresh memory is touched
  // twice; batches of 128 clusters keep them small.
  void buildClusters(int threads) {
    constexpr std::size_t kClustersPerChunk = 8, kChunksPerBatch = 16;
    std::vector<ClusterScratch> scratch(kChunksPerBatch);
    for (std::size_t batch = 0; batch < slots_.size(); batch += kClustersPerChunk * kChunksPerBatch) {
      const std::size_t end = std::min(slots_.size(), batch + kClustersPerChunk * kChunksPerBatch);
      const ChunkPlan plan(end - batch, kClustersPerChunk);
      parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t stop) {
        ClusterScratch& out = scratch[chunk];
        out.nodes.clear();
        out.leaves.clear();
        for (std::size_t c = batch + begin; c < batch + stop; ++c) buildCluster(slots_[c], out);
      });
      std::size_t total = bvh_.nodes_.size(), words = bvh_.leaves_.size();
      for (std::size_t c = batch; c < end; ++c) {
        slots_[c].firstNode = static_cast<std::uint32_t>(total);
        total += slots_[c].nodeCount;
        slots_[c].firstLeafWord = words;
        words += slots_[c].leafWords;
      }
      if (words > BvhNode::kMaxFirst) {
        throw std::length_error("bvh: " + std::to_string(8 * words) + " bytes of leaves, at most " +
                                std::to_string(8 * std::uint64_t(BvhNode::kMaxFirst)) + " supported");
      }
      // The batch's references are no longer read: their pages go back to the system as the leaves
      // that replace them are written, so that the two are never held whole.
      releaseReferencesBefore(slots_[end - 1].range.end);
      bvh_.nodes_.resize(total);
      bvh_.leaves_.resize(words);
      parallelChunks(plan, threads, [&](std::size_t chunk, std::size_t begin, std::size_t stop) {
        const ClusterScratch& out = scratch[chunk];
        for (std::size_t c = batch + begin; c < batch + stop; ++c) {
          const ClusterSlot& slot = slots_[c];
          std::memcpy(bvh_.leaves_.data() + slot.firstLeafWord, out.leaves.data() + slot.leafStart,
                      slot.leafWords * sizeof(std::uint64_t));
          if (slot.nodeCount == 0)
            continue;  // a leaf cluster: no nodes in the scratch (its data() may be null)
          BvhNode* to = bvh_.nodes_.data() + slot.firstNode;
          std::memcpy(static_cast<void*>(to), out.nodes.data() + slot.scratchStart,
                      slot.nodeCount * sizeof(BvhNode));
          for (std::uint32_t n = 0; n < slot.nodeCount; ++n) {
            for (std::uint32_t& code : to[n].child) {
              if (code == BvhNode::kEmpty) continue;
              code = BvhNode::isLeaf(code) ? movedLeaf(code, slot.firstLeafWord) : code + slot.firstNode;
            }
          }
        }
      });
    }
  }
  // Gives the pages wholly below reference `end` back to the system (they read as zeros after).
  void releaseReferencesBefore(std::uint32_t end) {
    constexpr std::uintptr_t kPage = 4096;
    const auto begin = reinterpret_cast<std::uintptr_t>(refs_.data());
    const std::uintptr_t first = (begin + kPage - 1) & ~(kPage - 1);
    const std::uintptr_t last = (begin + std::uintptr_t(end) * sizeof(PrimRef)) & ~(kPage - 1);
    if (last > released_ && last > first) {
      const std::uintptr_t from = std::max(first, released_);
      ::madvise(reinterpret_cast<void*>(from), last - from, MADV_DONTNEED);
      released_ = last;
    }
  }

  void build(const std::vector<Cluster>& clusters, int threads) {
    const std::size_t count = clusters.size();
    slots_.resize(count);
    parallelFor(count, threads, 64, [&](std::size_t c) {
      slots_[c].range = rangeOf(refs_.data(), clusters[c].begin, clusters[c].end);
    });
    std::uint64_t triangles = 0;
    for (const ClusterSlot& slot : slots_) triangles += slot.range.triangles;
    // Room for every node (at most one a reference, and the root) and the largest leaves (three
    // vertices of their own a triangle: BvhLeaf::words of one triangle is at most 14 + 43 bytes),
    // touched only where written.
    bvh_.nodes_.reserve(refs_.size() + 1);
    adviseHugePages(bvh_.nodes_);
    bvh_.leaves_.reserve((14 * refs_.size() + 43 * triangles) / 8 + 1 + kLeafTailWords);
    adviseHugePages(bvh_.leaves_);
    if (count > 1) {
      std::vector<PrimRef> top(count);
      for (std::size_t c = 0; c < count; ++c) {
        const Range& range = slots_[c].range;
        PrimRef& r = top[c];
        std::copy(range.bounds.lo, range.bounds.lo + 3, r.lo);
        std::copy(range.bounds.hi, range.bounds.hi + 3, r.hi);
        r.face = static_cast<std::uint32_t>(c);
        r.triangles = range.triangles;
      }
      Range all = rangeOf(top.data(), 0, static_cast<std::uint32_t>(count));
      all.split = chooseSplit(top.data(), all, options_, LeafRule::SingleReference);
      writeTop(top, all, 0);
    }
    buildClusters(threads);
    if (count == 1 && BvhNode::isLeaf(slots_[0].code)) {
      // A single leaf: the root holds it.
      bvh_.nodes_.emplace_back().clear();
      setLane(bvh_.nodes_[0], 0, slots_[0].range.bounds);
      ++topCounts_.nodes;
    }
    // Each cluster into the lane that holds it (with one cluster of nodes, its root is the tree's).
    for (ClusterSlot& slot : slots_) {
      const bool leaf = BvhNode::isLeaf(slot.code);
      if (count > 1 || leaf) {
        bvh_.nodes_[slot.topNode].child[slot.topLane] =
            leaf ? movedLeaf(slot.code, slot.firstLeafWord) : slot.code + slot.firstNode;
      }
      topCounts_.add(slot.counts);
    }
    bvh_.leaves_.resize(bvh_.leaves_.size() + kLeafTailWords, 0);
  }

  std::span<const Vec3> positions_;
  std::span<const MeshFace> faces_;
  HugePageArray<PrimRef>& refs_;
  const BvhBuildOptions& options_;
  Bvh& bvh_;
  std::vector<ClusterSlot> slots_;
  TreeCounts topCounts_;
  std::uintptr_t released_ = 0;  // the references' pages below this address are given back
};

Bvh Bvh::build(std::span<const Vec3> positions, std::span<const MeshFace> faces,
               const BvhBuildOptions& options) {
  const Stopwatch stopwatch;
  Bvh bvh;
  bvh.traversalCost_ = options.traversalCost;
  bvh.intersectionCost_ = options.intersectionCost;
  const int threads = resolveThreadCount(options.threads);
  MortonFaces gathered = gatherMortonFaces(
      positions, faces, std::clamp<std::uint32_t>(options.maxClusterReferences, 1, kMaxClusterReferences),
      threads);
  bvh.slivers_ = std::move(gathered.slivers);
  HugePageArray<PrimRef>& refs = gathered.refs;
  bvh.stats_.kind = "bvh";
  bvh.stats_.faces = faces.size();
  Aabb box;
  if (refs.empty()) {
    bvh.nodes_.emplace_back().clear();
    bvh.stats_.nodes = 1;
  } else {
    BvhBuilder builder(positions, faces, refs, options, bvh);
    builder.build(gathered.clusters, threads);
    for (const ClusterSlot& slot : builder.slots_) box.extend(slot.range.bounds.aabb());
    AccelStats& stats = bvh.stats_;
    stats.nodes = builder.topCounts_.nodes;
    stats.leaves = builder.topCounts_.leaves;
    stats.triangleReferences = builder.topCounts_.triangleReferences;
    stats.depth = builder.topCounts_.depth;
  }
  refs.reset();
  bvh.setBounds(box);
  AccelStats& stats = bvh.stats_;
  stats.triangles = stats.triangleReferences + bvh.slivers_.size();
  stats.meanTrianglesPerLeaf = stats.leaves ? double(stats.triangleReferences) / double(stats.leaves) : 0.0;
  // What the structure holds (the nodes' array keeps untouched room for the worst case).
  stats.bytes = bvh.nodes_.size() * sizeof(BvhNode) + bvh.leaves_.size() * sizeof(std::uint64_t) +
                bvh.slivers_.size() * sizeof(PackedTriangle);
  stats.sahCost = bvh.builtSahCost_ = bvh.sahCost();
  stats.buildSeconds = stopwatch.seconds();
  return bvh;
}

}  // namespace lancer
