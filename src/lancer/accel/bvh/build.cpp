// The BVH build: binned SAH over face references (Wald 2007, "On fast construction of SAH-based
// bounding volume hierarchies"; 32 bins of the centroids per axis), collapsed into 8-wide nodes as it
// goes (Embree's BVHBuilderBinnedSAH: a node's child of largest area is split until it has eight),
// then laid out depth first. A quad is one reference, its two triangles kept together in one leaf.
// Determinism: a range's bins are exact (minima, maxima, integer counts) however its references are
// chunked, and every partition is serial, so the tree depends on the faces alone; threads only
// change who builds which subtree (the top ranges bin on every thread, then whole subtrees go to the
// threads, biggest first).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "lancer/accel/build_threads.hpp"
#include "lancer/accel/bvh/build_parts.hpp"
#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/parallel_for.hpp"
#include "lancer/util/stopwatch.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {

using namespace bvh;

namespace {

// A node of the build: the ranges of its children, and for each inner child its node.
struct BuildNode {
  int count = 0;
  Range child[BvhNode::kWidth];
  BuildNode* node[BvhNode::kWidth] = {};
};

// Build nodes for any number of threads; deques keep addresses stable.
class BuildNodes {
 public:
  std::deque<BuildNode>& create() {
    std::lock_guard lock(mutex_);
    return pools_.emplace_back();
  }

 private:
  std::mutex mutex_;
  std::deque<std::deque<BuildNode>> pools_;
};

// An inner child of the parallel top, built later as a whole subtree on one thread.
struct Subtree {
  Range range;
  BuildNode** slot;
};

}  // namespace

struct BvhBuilder {
  BvhBuilder(std::vector<PrimRef>& refs, const BvhBuildOptions& options)
      : refs_(refs), options_(options), threads_(resolveThreadCount(options.threads)) {
    const std::size_t n = refs.size();
    topAbove_ = options.parallelTopAbove > 0
                    ? options.parallelTopAbove
                    : std::max<std::size_t>(1 << 14, n / (4 * std::size_t(threads_)));
    if (threads_ == 1 && options.parallelTopAbove == 0) topAbove_ = n;
  }

  BuildNode* buildRoot(const Range& all) {
    Range root = all;
    decide(root, root.count() > topAbove_);
    std::deque<BuildNode>& pool = nodes_.create();
    BuildNode* top = buildNode(root, pool, true);
    // Biggest subtrees first, each on whichever thread is free.
    std::stable_sort(subtrees_.begin(), subtrees_.end(),
                     [](const Subtree& a, const Subtree& b) { return a.range.count() > b.range.count(); });
    BuildThreads threads(threads_);
    threads.runEach(std::span<Subtree>(subtrees_), [&](const Subtree& subtree) {
      *subtree.slot = buildNode(subtree.range, nodes_.create(), false);
    });
    return top;
  }

  // Fills a node from `range` (already decided to split): its child of largest area is split until
  // it has eight or none can be; inner children become nodes (the top defers small ones).
  BuildNode* buildNode(const Range& range, std::deque<BuildNode>& pool, bool top) {
    BuildNode& node = pool.emplace_back();
    node.child[0] = range;
    node.count = 1;
    while (node.count < BvhNode::kWidth) {
      int pick = -1;
      float largest = -1.0f;
      for (int k = 0; k < node.count; ++k) {
        const float area = node.child[k].bounds.area();
        if (node.child[k].split.kind != SplitKind::Leaf && area > largest) {
          largest = area;
          pick = k;
        }
      }
      if (pick < 0) break;
      Range left, right;
      const bool parallel = top && node.child[pick].count() > topAbove_;
      partition(refs_.data(), node.child[pick], left, right);
      decide(left, parallel && left.count() > topAbove_);
      decide(right, parallel && right.count() > topAbove_);
      node.child[pick] = left;
      node.child[node.count++] = right;
    }
    for (int k = 0; k < node.count; ++k) {
      const Range& child = node.child[k];
      if (child.split.kind == SplitKind::Leaf) continue;
      if (!top) {
        node.node[k] = buildNode(child, pool, false);
      } else if (child.count() > topAbove_) {
        node.node[k] = buildNode(child, pool, true);
      } else {
        subtrees_.push_back({child, &node.node[k]});
      }
    }
    return &node;
  }

  void decide(Range& range, bool parallel) const {
    range.split = chooseSplit(refs_.data(), range, options_, parallel ? threads_ : 1);
  }

  std::vector<PrimRef>& refs_;
  const BvhBuildOptions& options_;
  int threads_;
  std::size_t topAbove_ = 0;
  BuildNodes nodes_;
  std::vector<Subtree> subtrees_;
};

namespace {

void setLane(BvhNode& node, int k, const Box& box) {
  for (int a = 0; a < 3; ++a) {
    node.lower[a][k] = box.lo[a];
    node.upper[a][k] = box.hi[a];
  }
}

// Depth first from the root at 0; a leaf's triangles are its references' (firstTriangle: the
// prefix of their triangle counts in reference order).
struct Flattener {
  std::vector<BvhNode>& nodes;
  const std::vector<std::uint32_t>& firstTriangle;
  AccelStats& stats;

  std::uint32_t flatten(const BuildNode& build, std::uint64_t depth) {
    const auto index = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back().clear();
    ++stats.nodes;
    stats.depth = std::max(stats.depth, depth);
    for (int k = 0; k < build.count; ++k) {
      const Range& child = build.child[k];
      std::uint32_t code;
      if (build.node[k] != nullptr) {
        code = flatten(*build.node[k], depth + 1);
      } else {
        const std::uint32_t first = firstTriangle[child.begin];
        const std::uint32_t count = firstTriangle[child.end] - first;
        code = BvhNode::leaf(first, count);
        ++stats.nodes;
        ++stats.leaves;
        stats.triangleReferences += count;
      }
      setLane(nodes[index], k, child.bounds);
      nodes[index].child[k] = code;
    }
    return index;
  }
};

}  // namespace

Bvh Bvh::build(std::span<const Vec3> positions, std::span<const MeshFace> faces,
               const BvhBuildOptions& options) {
  const Stopwatch stopwatch;
  Bvh bvh;
  bvh.traversalCost_ = options.traversalCost;
  bvh.intersectionCost_ = options.intersectionCost;
  const int threads = resolveThreadCount(options.threads);
  GatheredFaces gathered = gatherFaces(positions, faces, threads);
  bvh.slivers_ = std::move(gathered.slivers);
  std::vector<PrimRef>& refs = gathered.refs;
  const std::size_t n = refs.size();
  Range all = rangeOf(refs.data(), 0, static_cast<std::uint32_t>(n));
  bvh.stats_.kind = "bvh";
  bvh.stats_.faces = faces.size();
  std::vector<std::uint32_t> firstTriangle(n + 1, 0);
  BvhBuilder builder(refs, options);
  BuildNode* root = nullptr;
  if (n > 0) root = builder.buildRoot(all);
  for (std::size_t i = 0; i < n; ++i) firstTriangle[i + 1] = firstTriangle[i] + refs[i].triangles;
  if (firstTriangle[n] > BvhNode::kMaxFirst) {
    throw std::length_error("bvh: " + std::to_string(firstTriangle[n]) + " triangles, at most " +
                            std::to_string(BvhNode::kMaxFirst) + " supported");
  }
  // The triangles in reference order, which is leaf order.
  bvh.triangles_ = vectorOnHugePages<PackedTriangle>(firstTriangle[n]);
  parallelFor(n, threads, 1 << 14, [&](std::size_t i) {
    const MeshFace& face = faces[refs[i].face];
    PackedTriangle* out = bvh.triangles_.data() + firstTriangle[i];
    out[0] = {positions[face.vertex[0]], positions[face.vertex[1]], positions[face.vertex[2]], refs[i].face};
    if (face.isQuad())
      out[1] = {positions[face.vertex[0]], positions[face.vertex[2]], positions[face.vertex[3]],
                refs[i].face};
  });
  std::vector<PrimRef>().swap(refs);
  const Aabb box = all.bounds.aabb();
  Flattener flattener{bvh.nodes_, firstTriangle, bvh.stats_};
  if (root != nullptr) {
    bvh.nodes_.reserve(std::max<std::size_t>(1, n / 16));
    flattener.flatten(*root, 0);
    bvh.nodes_.shrink_to_fit();
  } else {
    bvh.nodes_.emplace_back().clear();
    bvh.stats_.nodes = 1;
  }
  bvh.setBounds(box);
  AccelStats& stats = bvh.stats_;
  stats.triangles = bvh.triangles_.size() + bvh.slivers_.size();
  stats.meanTrianglesPerLeaf = stats.leaves ? double(stats.triangleReferences) / double(stats.leaves) : 0.0;
  stats.bytes = bvh.nodes_.capacity() * sizeof(BvhNode) +
                (bvh.triangles_.capacity() + bvh.slivers_.capacity()) * sizeof(PackedTriangle);
  stats.sahCost = bvh.builtSahCost_ = bvh.sahCost();
  stats.buildSeconds = stopwatch.seconds();
  return bvh;
}

}  // namespace lancer
