// The accelerator the renderer holds: one of the kd-tree builds or the brute-force reference,
// chosen by name (`--accel`), behind one value type with no virtual call per ray.
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <variant>

#include "lancer/accel/accel_stats.hpp"
#include "lancer/accel/hit.hpp"
#include "lancer/accel/hit_filter.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "lancer/accel/ray_packet.hpp"

namespace lancer {

enum class AccelKind { KdTreeSah, KdTreeSahExact, KdTreeMedian, Naive };

// The names `--accel` takes, in AccelKind's order.
inline constexpr std::array<std::string_view, 4> kAccelNames = {"kdtree-sah", "kdtree-sah-exact",
                                                                "kdtree-median", "naive"};

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
    if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return tree->intersect(ray, tMin, tMax, hit);
    return std::get<NaiveAccel>(impl_).intersect(ray, tMin, tMax, hit);
  }
  // Any hit with t in (tMin, tMax).
  bool occluded(const Ray& ray, float tMin, float tMax) const {
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

  AccelKind kind() const { return kind_; }
  AccelStats stats() const { return stats_; }

 private:
  Accelerator(std::variant<KdTree, NaiveAccel> impl, AccelKind kind, AccelStats stats)
      : impl_(std::move(impl)), kind_(kind), stats_(std::move(stats)) {}

  std::variant<KdTree, NaiveAccel> impl_;
  AccelKind kind_;
  AccelStats stats_;
};

}  // namespace lancer
