// The accelerator the renderer holds, chosen by name (`--accel`), behind one value type with no
// virtual call per ray. A map of accel/ (docs/accelerators.md says more):
//
//   default   bvh/        the wide BVH (`bvh`): bvh.hpp the interface; build.cpp and build_parts.*
//                         the binned-SAH build collapsed into 8-wide nodes (node.hpp); traversal.cpp
//                         single rays, packet_traversal.cpp packets; box_test.hpp the 8-box AVX2 test;
//                         leaf_test.hpp the leaf's triangles; refit.cpp refit for moved vertices.
//   reference naive_accel.hpp  brute force: every triangle; what every accelerator must equal.
//   second    kd_tree.hpp, kd/ the seed's kd-tree (`kdtree-sah`, `kdtree-sah-exact`, `kdtree-median`),
//                         kept selectable and tested: kd/binned_build.cpp its default build.
//   shared    triangle_intersect.* the watertight triangle test every accelerator uses; hit.hpp the
//                         hit and its tie rule; hit_filter.hpp refusable hits; ray_packet.hpp packets;
//                         kd/query.hpp and kd/packet_frame.hpp the closest/any-hit bookkeeping and
//                         the 8-lane triangle tests both trees call.
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <variant>

#include "lancer/accel/accel_stats.hpp"
#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/accel/hit.hpp"
#include "lancer/accel/hit_filter.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "lancer/accel/ray_packet.hpp"

namespace lancer {

enum class AccelKind { Bvh, KdTreeSah, KdTreeSahExact, KdTreeMedian, Naive };

// The names `--accel` takes, in AccelKind's order.
inline constexpr std::array<std::string_view, 5> kAccelNames = {"bvh", "kdtree-sah", "kdtree-sah-exact",
                                                                "kdtree-median", "naive"};

// What the CLI, the scene loader and Python build unless told otherwise.
inline constexpr AccelKind kDefaultAccel = AccelKind::Bvh;
inline constexpr std::string_view kDefaultAccelName = kAccelNames[static_cast<std::size_t>(kDefaultAccel)];

// One of kAccelNames; throws std::invalid_argument naming the choices otherwise (the CLI turns it
// into its usage error).
AccelKind parseAccelKind(std::string_view name);
std::string_view accelKindName(AccelKind kind);

class Accelerator {
 public:
  static Accelerator build(std::span<const Vec3> positions, std::span<const MeshFace> faces, AccelKind kind,
                           const KdBuildOptions& options = {});

  // Closest hit with t in (tMin, tMax), ties to the lower face; false (hit untouched) when none.
  bool intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const {
    if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->intersect(ray, tMin, tMax, hit);
    if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->intersect(ray, tMin, tMax, hit);
    return std::get<NaiveAccel>(impl_).intersect(ray, tMin, tMax, hit);
  }
  // Any hit with t in (tMin, tMax).
  bool occluded(const Ray& ray, float tMin, float tMax) const {
    if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return bvh->occluded(ray, tMin, tMax);
    if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->occluded(ray, tMin, tMax);
    return std::get<NaiveAccel>(impl_).occluded(ray, tMin, tMax);
  }

  // The same two queries seeing only the hits `filter` keeps (the renderer's per-mesh cut views).
  // Out of line: the rare path stays out of the code of callers that choose between these and the
  // plain queries once per ray (the tracer).
  bool intersect(const Ray& ray, float tMin, float tMax, const HitFilter& filter, Hit& hit) const;
  bool occluded(const Ray& ray, float tMin, float tMax, const HitFilter& filter) const;

  // The packet queries (KdTree's; the brute-force reference answers lane by lane). Return the lanes
  // of `active` that hit, or are occluded; hits[i] is set for each lane i that hit.
  std::uint32_t intersect(const RayPacket& packet, std::uint32_t active,
                          std::span<Hit, kPacketSize> hits) const;
  std::uint32_t occluded(const RayPacket& packet, std::uint32_t active) const;
  std::uint32_t intersect(const RayPacket& packet, std::uint32_t active, const HitFilter& filter,
                          std::span<Hit, kPacketSize> hits) const;
  std::uint32_t occluded(const RayPacket& packet, std::uint32_t active, const HitFilter& filter) const;

  // A new time step of the same mesh (same faces, moved vertices; animation): the BVH is refitted
  // (Bvh::refit) unless that cannot stay exact or its SAH cost grew past Bvh::kRebuildAboveGrowth,
  // every other kind is built again. Returns whether it refitted.
  bool update(std::span<const Vec3> positions, std::span<const MeshFace> faces,
              const KdBuildOptions& options = {});

  AccelKind kind() const { return kind_; }
  AccelStats stats() const { return stats_; }

 private:
  using Impl = std::variant<Bvh, KdTree, NaiveAccel>;
  Accelerator(Impl impl, AccelKind kind, AccelStats stats)
      : impl_(std::move(impl)), kind_(kind), stats_(std::move(stats)) {}

  Impl impl_;
  AccelKind kind_;
  AccelStats stats_;
};

}  // namespace lancer
