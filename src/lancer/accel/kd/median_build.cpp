// The spatial-median kd-tree (--accel kdtree-median), the simple baseline: split the longest side of
// the cell at its middle and send each triangle to every child its bounding box touches, until a
// cell holds few enough triangles.
#include <algorithm>
#include <chrono>
#include <future>

#include "lancer/accel/build_threads.hpp"
#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd_tree.hpp"

namespace lancer {

namespace {

class MedianBuilder {
 public:
  MedianBuilder(const KdBuildInput& input, const KdBuildOptions& options, BuildArenas& arenas)
      : arenas_(arenas),
        rootBox_(input.bounds),
        maxDepth_(resolveMaxDepth(options, input.triangles.size())),
        leafSize_(static_cast<std::uint32_t>(std::max(1, options.medianLeafSize))),
        forks_(resolveThreads(options)) {
    bounds_.reserve(input.triangles.size());
    for (const PackedTriangle& triangle : input.triangles) {
      Aabb box;
      for (const Vec3& v : cornersOf(triangle)) box.extend(v);
      bounds_.push_back(box);
    }
  }

  BuildNode* buildRoot() {
    std::vector<std::uint32_t> all(bounds_.size());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    return build(all, rootBox_, 0, 0, arenas_.create());
  }

 private:
  // badSplits counts splits on the path that left both children with most of the triangles (big
  // triangles spanning the cell); after kMaxBadSplits of them the cell becomes a leaf (pbrt-v3's
  // "bad refines"), else a soup of large triangles would split down to the depth limit.
  BuildNode* build(std::vector<std::uint32_t>& triangles, const Aabb& box, int depth, int badSplits,
                   BuildArena& arena) {
    if (triangles.size() <= leafSize_ || depth >= maxDepth_) return arena.leaf(triangles);
    const int axis = box.longestAxis();
    const float split = 0.5f * (box.lower[axis] + box.upper[axis]);
    if (!(split > box.lower[axis] && split < box.upper[axis])) return arena.leaf(triangles);
    std::vector<std::uint32_t> left, right;
    for (std::uint32_t t : triangles) {
      if (bounds_[t].lower[axis] <= split) left.push_back(t);
      if (bounds_[t].upper[axis] >= split) right.push_back(t);
    }
    if (10 * std::min(left.size(), right.size()) > 9 * triangles.size() && ++badSplits > kMaxBadSplits) {
      return arena.leaf(triangles);
    }
    std::vector<std::uint32_t>().swap(triangles);
    Aabb leftBox = box, rightBox = box;
    leftBox.upper[axis] = split;
    rightBox.lower[axis] = split;
    BuildNode *leftNode = nullptr, *rightNode = nullptr;
    std::future<void> task;
    if (depth < kForkDepth) {
      task = forks_.fork([&] { leftNode = build(left, leftBox, depth + 1, badSplits, arenas_.create()); });
    }
    if (task.valid()) {
      rightNode = build(right, rightBox, depth + 1, badSplits, arena);
      forks_.join(task);
    } else {
      leftNode = build(left, leftBox, depth + 1, badSplits, arena);
      rightNode = build(right, rightBox, depth + 1, badSplits, arena);
    }
    return arena.inner(axis, split, leftNode, rightNode);
  }

  static constexpr int kMaxBadSplits = 3;
  static constexpr int kForkDepth = 3;  // only the top levels fork, while a thread is free

  BuildArenas& arenas_;
  Aabb rootBox_;
  std::vector<Aabb> bounds_;
  int maxDepth_;
  std::uint32_t leafSize_;
  BuildThreads forks_;
};

}  // namespace

KdTree KdTree::buildMedian(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                           const KdBuildOptions& options) {
  return KdTreeAssembler::build<MedianBuilder>(positions, faces, options, /*withCorners=*/false,
                                               "kdtree-median");
}

}  // namespace lancer
