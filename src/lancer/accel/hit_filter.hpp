// A filter on candidate hits, for queries that must see through some faces (the renderer's per-mesh
// cut views): the accelerators know that a hit can be refused, not why.
#pragma once

#include <cstdint>

#include "lancer/math/ray.hpp"

namespace lancer {

// `keeps(context, ray, face, t)` says whether the hit of `face` at t counts. Called only for a hit
// that would otherwise be taken, never per triangle test, so an indirect call is cheap enough there;
// scenes without a filter use the unfiltered queries, which make no call at all.
// `ray` is the query's own object: in a packet query, the lane's packet.ray[i] itself, so that a
// filter can tell lanes apart by address. A filter that refuses every hit is shown every face the
// ray meets in its interval (a face cut into several leaves maybe more than once), with the t the
// closest-hit query would give: the renderer's shadow rays through glass collect their faces so
// (tests/accel/packet_query_property_test.cpp checks both).
struct HitFilter {
  const void* context = nullptr;
  bool (*keeps)(const void* context, const Ray& ray, std::uint32_t face, float t) = nullptr;

  bool operator()(const Ray& ray, std::uint32_t face, float t) const { return keeps(context, ray, face, t); }
};

// Every hit counts: the filter of the unfiltered queries, compiled away.
struct KeepEveryHit {
  bool operator()(const Ray&, std::uint32_t, float) const { return true; }
};

}  // namespace lancer
