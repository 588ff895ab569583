// The eight queries every accelerator answers (closest hit and any hit, for one ray or a packet,
// with or without a hit filter), written once as entries into the four walks each tree provides
// (Embree's intersector epilogue: one traversal, a filter policy; see hit_filter.hpp).
#pragma once

#include <bit>
#include <cstdint>
#include <span>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/hit_filter.hpp"
#include "lancer/accel/ray_packet.hpp"
#include "lancer/math/ray.hpp"

namespace lancer {

// Tree (Bvh, KdTree, NaiveAccel, Accelerator) provides, for Filter = KeepEveryHit and HitFilter:
//   bool closestHit(ray, tMin, tMax, keeps, hit), bool anyHit(ray, tMin, tMax, keeps),
//   uint32_t closestHits(packet, active, keeps, hits), uint32_t anyHits(packet, active, keeps).
template <typename Tree>
class TreeQueries {
 public:
  // Closest hit with t in (tMin, tMax), ties to the lower face; false (hit untouched) when none.
  bool intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const {
    return tree().closestHit(ray, tMin, tMax, KeepEveryHit{}, hit);
  }
  // Any hit with t in (tMin, tMax): the shadow-ray query, stops at the first blocker.
  bool occluded(const Ray& ray, float tMin, float tMax) const {
    return tree().anyHit(ray, tMin, tMax, KeepEveryHit{});
  }
  // The same two queries seeing only the hits `filter` keeps (a refused face is passed through, and
  // casts no shadow). Separate entry points: queries without a filter pay nothing for it.
  bool intersect(const Ray& ray, float tMin, float tMax, const HitFilter& filter, Hit& hit) const {
    return tree().closestHit(ray, tMin, tMax, filter, hit);
  }
  bool occluded(const Ray& ray, float tMin, float tMax, const HitFilter& filter) const {
    return tree().anyHit(ray, tMin, tMax, filter);
  }

  // The same queries for the lanes `active` of a packet. Each lane's answer is the single ray's, to
  // the bit. Return the lanes that hit (or are occluded); hits[i] is set for each lane i that hit.
  std::uint32_t intersect(const RayPacket& packet, std::uint32_t active,
                          std::span<Hit, kPacketSize> hits) const {
    return tree().closestHits(packet, active, KeepEveryHit{}, hits);
  }
  std::uint32_t occluded(const RayPacket& packet, std::uint32_t active) const {
    return tree().anyHits(packet, active, KeepEveryHit{});
  }
  std::uint32_t intersect(const RayPacket& packet, std::uint32_t active, const HitFilter& filter,
                          std::span<Hit, kPacketSize> hits) const {
    return tree().closestHits(packet, active, filter, hits);
  }
  std::uint32_t occluded(const RayPacket& packet, std::uint32_t active, const HitFilter& filter) const {
    return tree().anyHits(packet, active, filter);
  }

 protected:
  // The packet queries as single rays, lane by lane: the brute-force reference, builds without AVX2,
  // a lone lane, and kd packets whose rays diverge.
  template <typename Filter>
  std::uint32_t closestHitsOneByOne(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                                    std::span<Hit, kPacketSize> hits) const {
    std::uint32_t hitLanes = 0;
    for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      if (tree().closestHit(packet.ray[i], packet.tMin[i], packet.tMax[i], keeps, hits[i]))
        hitLanes |= 1u << i;
    }
    return hitLanes;
  }
  template <typename Filter>
  std::uint32_t anyHitsOneByOne(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
    std::uint32_t hitLanes = 0;
    for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      if (tree().anyHit(packet.ray[i], packet.tMin[i], packet.tMax[i], keeps)) hitLanes |= 1u << i;
    }
    return hitLanes;
  }

 private:
  const Tree& tree() const { return static_cast<const Tree&>(*this); }
};

}  // namespace lancer
