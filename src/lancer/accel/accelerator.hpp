// The accelerator the renderer holds, chosen by name (`--accel`), behind one value type with no
// virtual call per ray. accel/README.md maps the folder: bvh/ the default, naive_accel.hpp the
// reference, kd_tree.hpp and kd/ the original kd-tree kept selectable.
#pragma once

#include <array>
#include <functional>
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
#include "lancer/accel/tree_queries.hpp"

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

class Accelerator : public TreeQueries<Accelerator> {
 public:
  static Accelerator build(std::span<const Vec3> positions, std::span<const MeshFace> faces, AccelKind kind,
                           const KdBuildOptions& options = {});

  // The walks behind TreeQueries' eight queries: the chosen tree's (no virtual call per ray).
  template <typename Filter>
  bool closestHit(const Ray& ray, float tMin, float tMax, const Filter& keeps, Hit& hit) const {
    return visit([&](const auto& tree) { return tree.closestHit(ray, tMin, tMax, keeps, hit); });
  }
  template <typename Filter>
  bool anyHit(const Ray& ray, float tMin, float tMax, const Filter& keeps) const {
    return visit([&](const auto& tree) { return tree.anyHit(ray, tMin, tMax, keeps); });
  }
  template <typename Filter>
  std::uint32_t closestHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                            std::span<Hit, kPacketSize> hits) const {
    return visit([&](const auto& tree) { return tree.closestHits(packet, active, keeps, hits); });
  }
  template <typename Filter>
  std::uint32_t anyHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
    return visit([&](const auto& tree) { return tree.anyHits(packet, active, keeps); });
  }

  // A new time step of the same mesh (same faces, moved vertices; animation): the BVH is refitted
  // (Bvh::refit) unless that cannot stay exact or its SAH cost grew past Bvh::kRebuildAboveGrowth,
  // every other kind is built again, after the old tree is freed and `beforeBuild` called (to free
  // more before the build's peak). Returns whether it refitted.
  bool update(std::span<const Vec3> positions, std::span<const MeshFace> faces,
              const KdBuildOptions& options = {}, const std::function<void()>& beforeBuild = {});

  AccelKind kind() const { return kind_; }
  AccelStats stats() const { return stats_; }

 private:
  using Impl = std::variant<Bvh, KdTree, NaiveAccel>;
  Accelerator(Impl impl, AccelKind kind, AccelStats stats)
      : impl_(std::move(impl)), kind_(kind), stats_(std::move(stats)) {}
  static Accelerator kdTree(KdTree tree, AccelKind kind);
  // `query` on the tree held, the default first.
  template <typename Query>
  auto visit(const Query& query) const {
    if (const Bvh* bvh = std::get_if<Bvh>(&impl_)) return query(*bvh);
    if (const KdTree* tree = std::get_if<KdTree>(&impl_)) return query(*tree);
    return query(std::get<NaiveAccel>(impl_));
  }

  Impl impl_;
  AccelKind kind_;
  AccelStats stats_;
};

}  // namespace lancer
