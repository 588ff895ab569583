// The default accelerator: a bounding volume hierarchy of 8-wide nodes (Wald, Benthin & Boulos 2008,
// "Getting rid of packets"; Embree's BVH8), built by binned SAH over Morton-ordered clusters of faces and
// inside them, with the children's boxes tested in one AVX2 step and leaves of pre-gathered triangles.
// Answers equal NaiveAccel's exactly (the shared watertight test, ties to the lower face), so images equal
// the kd-tree's.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "lancer/accel/accel_stats.hpp"
#include "lancer/accel/bvh/leaf.hpp"
#include "lancer/accel/bvh/node.hpp"
#include "lancer/accel/tree_queries.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/aabb.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/util/isa.hpp"

namespace lancer {

struct BvhBuildOptions {
  // SAH cost constants of a binary split (the wide nodes are collapsed from binary splits): a node
  // step and a triangle test, in the same unit. Tuned on the 1M bench bracket, 1 thread, Mrays/s
  // primary / shadow / incoherent: (1, 1) 10.4 / 10.8 / 1.49 with 1.8 triangles a leaf; (2, 1)
  // 11.0 / 12.1 / 1.93; (4, 1) 12.2 / 13.5 / 2.16 with 5.8 a leaf, and a third faster to build;
  // (6, 1) and (8, 1) alike within noise (leaves are capped at eight triangles).
  float traversalCost = 4.0f;
  float intersectionCost = 1.0f;
  // Build threads; 0 uses every hardware thread. The tree does not depend on it.
  int threads = 0;
  // Most face references in a cluster (1 to 512): the build sorts the faces in Morton order, cuts
  // that order into clusters of nearby faces, builds each cluster's subtree on its own (on every
  // thread) and the top of the tree over the clusters. Smaller clusters build faster and make a
  // costlier tree (tests set it low to reach the top's code with few faces).
  std::uint32_t maxClusterReferences = 512;
};

class Bvh : public TreeQueries<Bvh> {
 public:
  static Bvh build(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                   const BvhBuildOptions& options = {});

  // The walks behind TreeQueries' eight queries, instantiated for KeepEveryHit and HitFilter:
  // single rays (bvh/traversal.cpp) and packets (bvh/packet_traversal.cpp: the active lanes walk
  // the tree once together, each child box tested for every lane, each leaf triangle for the lanes
  // that reached it).
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

  // Closest hits of independent rays (any origins and directions, unlike a packet's: a path tracer's
  // bounces), kRaysInFlight of them walked at once, a node or leaf of each in turn, so that one ray's
  // cache misses overlap the others' work (bvh/batch_traversal.cpp). hits[i] is what
  // intersect(rays[i], tMin, tMax[i], ...) gives, Hit{} for a miss; returns how many hit.
  static constexpr int kRaysInFlight = 4;
  std::size_t intersect(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                        std::span<Hit> hits) const {
    return closestHitsInFlight(rays, tMin, tMax, KeepEveryHit{}, hits);
  }
  std::size_t intersect(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                        const HitFilter& filter, std::span<Hit> hits) const {
    return closestHitsInFlight(rays, tMin, tMax, filter, hits);
  }
  using TreeQueries<Bvh>::intersect;
  // Any hits of independent rays (a path tracer's shadow rays), in flight the same way, children in
  // slot order: blocked[i] is 1 where occluded(rays[i], tMin, tMax[i], ...) is true, 0 elsewhere;
  // returns how many are blocked.
  std::size_t occluded(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                       std::span<std::uint8_t> blocked) const {
    return anyHitsInFlight(rays, tMin, tMax, KeepEveryHit{}, blocked);
  }
  std::size_t occluded(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                       const HitFilter& filter, std::span<std::uint8_t> blocked) const {
    return anyHitsInFlight(rays, tMin, tMax, filter, blocked);
  }
  using TreeQueries<Bvh>::occluded;

  // Refit (bvh/refit.cpp): the same faces at new `positions` (a deformed time step: same vertex
  // count, same topology), the tree kept and its boxes recomputed bottom up. Returns false, leaving
  // the tree unusable, when it cannot keep the answers exact (a face turned into a sliver, or the
  // vertex count changed): build again then. After a refit, sahGrowth() says how much worse the
  // kept tree is than when it was built; rebuildPays() is the rule for when a new build is worth its
  // time (bench/RESULTS.md measures refit at about a tenth of a build).
  // On `threads` threads (0: every core); the result does not depend on it.
  bool refit(std::span<const Vec3> positions, std::span<const MeshFace> faces, int threads = 0);
  double sahGrowth() const { return builtSahCost_ > 0 ? stats_.sahCost / builtSahCost_ : 1.0; }
  static constexpr double kRebuildAboveGrowth = 1.5;
  bool rebuildPays() const { return sahGrowth() > kRebuildAboveGrowth; }

  const AccelStats& stats() const { return stats_; }
  const Aabb& bounds() const { return bounds_; }

  // For tests: the nodes (root at 0, every node before its children), the leaves' words (bvh/leaf.hpp)
  // and the leaf a leaf code names.
  std::span<const BvhNode> nodes() const { return nodes_; }
  std::span<const std::uint64_t> leafWords() const { return leaves_; }
  bvh::BvhLeaf leaf(std::uint32_t code) const {
    return {leaves_.data() + BvhNode::leafFirst(code), BvhNode::leafCount(code)};
  }
  std::span<const PackedTriangle> slivers() const { return slivers_; }

 private:
  // The walks, one instantiation per copy of the kernels (Isa: an isa:: tag).
  template <typename Isa, typename Filter>
  bool closestHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const;
  template <typename Isa, typename Filter>
  bool anyHitOn(const Ray& ray, float tMin, float tMax, const Filter& keeps) const;
  template <typename Isa, typename Filter>
  std::uint32_t closestHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                              std::span<Hit, kPacketSize> hits) const;
  template <typename Filter>
  std::size_t closestHitsInFlight(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                                  const Filter& keeps, std::span<Hit> hits) const {
    return isa::dispatch(
        [&](auto isa) { return closestHitsInFlightOn<decltype(isa)>(rays, tMin, tMax, keeps, hits); });
  }
  template <typename Isa, typename Filter>
  std::size_t closestHitsInFlightOn(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                                    const Filter& keeps, std::span<Hit> hits) const;
  template <typename Filter>
  std::size_t anyHitsInFlight(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                              const Filter& keeps, std::span<std::uint8_t> blocked) const {
    return isa::dispatch(
        [&](auto isa) { return anyHitsInFlightOn<decltype(isa)>(rays, tMin, tMax, keeps, blocked); });
  }
  template <typename Isa, typename Filter>
  std::size_t anyHitsInFlightOn(std::span<const Ray> rays, float tMin, std::span<const float> tMax,
                                const Filter& keeps, std::span<std::uint8_t> blocked) const;
  template <typename Isa, typename Filter>
  std::uint32_t anyHitsOn(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const;

  friend struct BvhBuilder;

  // The SAH cost of the tree as it stands, in the build's units (stats_.sahCost).
  double sahCost() const;
  // The scene box of the tree's triangles, padded, and the largest coordinate in it.
  void setBounds(const Aabb& box) {
    bounds_ = paddedBounds(box);
    magnitude_ = box.empty() ? 0.0f : std::max(maxComponent(abs(box.lower)), maxComponent(abs(box.upper)));
  }

  std::vector<BvhNode> nodes_;
  // The leaves (bvh/leaf.hpp), each at its code's first word, in the order the build wrote them; a
  // quad's two halves are neighbours in one leaf, (0,1,2) first, so every traversal order tests them
  // as brute force does. kLeafTailWords more at the end.
  std::vector<std::uint64_t> leaves_;
  // Faces with a near-degenerate half, tested for every ray (see isSliverTriangle); in face order.
  std::vector<PackedTriangle> slivers_;
  Aabb bounds_;          // of the tree's triangles, padded
  float magnitude_ = 0;  // largest absolute coordinate, for the boxes' rounding slack
  float traversalCost_ = 1, intersectionCost_ = 1;
  double builtSahCost_ = 0;
  AccelStats stats_;
};

}  // namespace lancer
