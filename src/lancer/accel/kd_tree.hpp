// The kd-tree accelerator: build (surface-area heuristic or the brief's spatial median) and the
// front-to-back traversal for closest-hit and any-hit queries. Answers equal NaiveAccel's exactly.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/kd_tree_node.hpp"
#include "lancer/accel/kd_tree_stats.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/aabb.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/mesh/mesh.hpp"

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

class KdTree {
 public:
  static constexpr int kMaxDepth = 60;  // the traversal stack holds one entry per level

  static KdTree buildSah(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                         const KdBuildOptions& options = {});
  static KdTree buildMedian(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                            const KdBuildOptions& options = {});

  // Closest hit with t in (tMin, tMax), ties to the lower face; false (hit untouched) when none.
  // tMin >= 0 (rays start at their origin).
  bool intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const;
  // Any hit with t in (tMin, tMax): the shadow-ray query, stops at the first blocker.
  bool occluded(const Ray& ray, float tMin, float tMax) const;

  const AccelStats& stats() const { return stats_; }
  const Aabb& bounds() const { return bounds_; }

  // The layout, read by the builders' shared finishing step and by tests.
  std::span<const KdNode> nodes() const { return nodes_; }
  std::span<const std::uint32_t> leafTriangles() const { return leafTriangles_; }
  std::span<const PackedTriangle> triangles() const { return triangles_; }
  std::span<const PackedTriangle> slivers() const { return slivers_; }

 private:
  friend class KdTreeAssembler;

  std::vector<KdNode> nodes_;                 // root at 0, a pad, then children in adjacent pairs
  std::vector<std::uint32_t> leafTriangles_;  // triangle indices of the leaves with 2+ triangles
  std::vector<PackedTriangle> triangles_;     // in the order the leaves first reference them
  // Near-degenerate triangles, whose Moller-Trumbore hits can land far from the triangle: tested
  // for every ray (outside the tree) so answers still equal brute force. Empty for sane meshes.
  std::vector<PackedTriangle> slivers_;
  Aabb bounds_;                               // scene box, padded so boundary hits are inside
  float magnitude_ = 0;                       // largest absolute coordinate, for rounding slack
  AccelStats stats_;
};

}  // namespace lancer
