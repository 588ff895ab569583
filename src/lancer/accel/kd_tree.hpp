// The kd-tree accelerator: build (surface-area heuristic, or each cell's longest side split at its
// middle) and the front-to-back traversal for closest-hit and any-hit queries, whose answers equal
// NaiveAccel's exactly. The builders and the traversal are in accel/kd/.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/accel/accel_stats.hpp"
#include "lancer/accel/kd/node.hpp"
#include "lancer/accel/tree_queries.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/aabb.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/util/isa.hpp"

namespace lancer {

struct KdBuildOptions {
  // SAH cost constants (Wald & Havran 2006, section 3): traversal step and triangle test, in the
  // same unit. Tuned on the 1M-triangle bench bracket by rays per CPU-second: (2, 1), (3, 1) and
  // (4, 1) trace alike within the ~10% noise; (3, 1) takes 59 bytes per triangle against 77 for
  // (2, 1), and builds 1.5x faster. (1, 1) halves the triangle tests of incoherent rays but takes
  // 105 bytes per triangle.
  float traversalCost = 3.0f;
  float intersectionCost = 1.0f;
  // Cost multiplier for a split that cuts off empty space (1 - the paper's bonus of 0.2), granted
  // when the empty side is at least emptySpaceMinFraction of the cell's side.
  float emptySpaceFactor = 0.8f;
  float emptySpaceMinFraction = 0.1f;
  // Exact build (buildSahExact): cells holding more triangles than this are split by binning
  // (kd/binned_split.hpp, the default build's search) rather than by sweeping sorted events; 0 sweeps from
  // the root (the pure O(N log N) build).
  std::uint32_t binnedAbove = 4096;
  // Binning: a triangle that crosses the split plane is clipped to each child cell ("perfect
  // splits") when its box is at least this fraction of the cell along one of the other two axes;
  // a smaller one keeps its box cut at the plane, which is looser but costs no clipping. 0 clips
  // every one. Measured on the 1M bench bracket (bench/time_to_first_pixel.sh): binning down to 16
  // triangles and clipping none saves ~10% of the build's CPU time but traces 4-15% slower, so
  // the default clips all.
  float clipAboveFraction = 0.0f;
  // Binned build (the default): cells of more than this many triangles (and of more than
  // triangles / threads) are binned and partitioned by all build threads together; below, subtrees
  // go to the threads as they fall idle. Only the schedule changes with it, never the tree (tests
  // set it low to exercise the parallel top). High by default: on the 1M bench bracket the
  // parallel top's per-chunk buffers cost 2.46 CPU-seconds on 2 threads against 1.83 on 1, where
  // forking subtrees alone costs the same on both.
  std::uint32_t parallelSplitAbove = 1u << 22;
  // Deepest leaf; 0 picks 8 + 1.3 log2(triangles) (pbrt-v3 section 4.4.2), capped by kMaxDepth.
  int maxDepth = 0;
  // Median build: a node with at most this many triangles becomes a leaf.
  int medianLeafSize = 8;
  // Build threads; 0 uses every hardware thread.
  int threads = 0;
};

// Per-thread traversal counters, compiled in only with -DLANCER_KD_COUNTERS (profiling builds).
struct KdTraversalCounters {
  std::uint64_t rays = 0, innerNodes = 0, leaves = 0, triangleTests = 0;
};
KdTraversalCounters& kdTraversalCounters();

class KdTree : public TreeQueries<KdTree> {
 public:
  static constexpr int kMaxDepth = 60;  // the traversal stack holds one entry per level

  // Binned SAH from root to leaves (kd/binned_build.cpp): the default.
  static KdTree buildSah(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                         const KdBuildOptions& options = {});
  // Binned top, then Wald & Havran's exact event sweep with every straddler clipped to the cell
  // (kd/sah_build.cpp): the slower build the default's tree quality is measured against.
  static KdTree buildSahExact(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                              const KdBuildOptions& options = {});
  static KdTree buildMedian(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                            const KdBuildOptions& options = {});

  // The walks behind TreeQueries' eight queries (tMin >= 0: rays start at their origin),
  // instantiated for KeepEveryHit and HitFilter: single rays (kd/traversal.cpp) and packets
  // (kd/packet_traversal.cpp: traced together down the tree with 8-wide SIMD where the CPU has
  // AVX2, one by one otherwise or when the rays run in different directions).
  // Each runs the copy of the walk for the CPU (util/isa.hpp: baseline, or x86-64-v3 with AVX2).
  template <typename Filter>
  bool closestHit(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const {
    return isa::dispatch([&](auto isa) { return closestHitOn<decltype(isa)>(ray, tMin, tMax, keeps, hit); });
  }
  template <typename Filter>
  bool anyHit(const Ray& ray, float tMin, float tMax, const Filter& keeps) const {
    return isa::dispatch([&](auto isa) { return anyHitOn<decltype(isa)>(ray, tMin, tMax, keeps); });
  }
  template <typename Filter>
  std::uint32_t closestHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                            std::span<Hit, kPacketSize> hits) const {
    return isa::dispatch([&](auto isa) { return closestHitsOn<decltype(isa)>(packet, active, keeps, hits); });
  }
  template <typename Filter>
  std::uint32_t anyHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
    return isa::dispatch([&](auto isa) { return anyHitsOn<decltype(isa)>(packet, active, keeps); });
  }

  const AccelStats& stats() const { return stats_; }
  const Aabb& bounds() const { return bounds_; }

  // The layout, for tests: one stream of 8-byte words holding the nodes, the leaves' triangle
  // lists and the triangles themselves (see layout_). Only entries reached from the root at 0
  // are nodes; walk it with the accessors below.
  std::span<const KdNode> layout() const { return layout_; }
  // A leaf's triangles, as word offsets into the layout.
  std::span<const std::uint32_t> leafTriangles(const KdNode& leaf) const {
    if (leaf.triangleCount() <= 1) return {&leaf.payload, leaf.triangleCount()};
    return {reinterpret_cast<const std::uint32_t*>(layout_.data() + leaf.payload), leaf.triangleCount()};
  }
  const PackedTriangle& triangleAt(std::uint32_t offset) const {
    return *reinterpret_cast<const PackedTriangle*>(layout_.data() + offset);
  }
  std::span<const PackedTriangle> slivers() const { return slivers_; }

  // Words a triangle takes in the layout.
  static constexpr std::uint32_t kTriangleWords = sizeof(PackedTriangle) / sizeof(KdNode);
  static_assert(sizeof(PackedTriangle) % sizeof(KdNode) == 0 && alignof(PackedTriangle) <= alignof(KdNode));

 private:
  // The walks, one instantiation per copy of the kernels (Isa: an isa:: tag).
  template <typename Isa, typename Filter>
  bool closestHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const;
  template <typename Isa, typename Filter>
  bool anyHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps) const;
  template <typename Isa, typename Filter>
  std::uint32_t closestHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                              std::span<Hit, kPacketSize> hits) const;
  template <typename Isa, typename Filter>
  std::uint32_t anyHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const;

  friend class KdTreeAssembler;

  // Depth first from the root at 0 (then a pad): each inner node's child pair (16-byte aligned),
  // followed at once by what its leaf children hold: the list of a leaf of 2+ triangles (32-bit
  // word offsets, padded to whole words) and every triangle not already placed by an earlier leaf.
  // A ray that reaches a leaf so finds its list and most of its triangles in the cache lines
  // next to the node, instead of paying three dependent misses in three separate arrays. The
  // triangles are read in place (trivially copyable data written by memcpy, never modified).
  std::vector<KdNode> layout_;
  // Near-degenerate triangles, whose computed hits can land far from the triangle: tested
  // for every ray (outside the tree) so answers still equal brute force. Empty for sane meshes.
  std::vector<PackedTriangle> slivers_;
  Aabb bounds_;          // scene box, padded so boundary hits are inside
  float magnitude_ = 0;  // largest absolute coordinate, for rounding slack
  AccelStats stats_;
};

}  // namespace lancer
