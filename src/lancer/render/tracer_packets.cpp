// Primary rays in packets: the first hits of up to eight neighbouring primary rays, then their
// shadow rays to each light, traced as packets (accel/ray_packet.hpp) ahead of the shading, which
// then runs ray by ray as for single rays and takes each answer traced ahead for its own query.
#include <algorithm>
#include <bit>

#include "lancer/render/primary_ahead.hpp"
#include "lancer/render/ray_offset.hpp"
#include "lancer/render/tracer.hpp"

namespace lancer {
namespace {

bool sameBits(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
         std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y) &&
         std::bit_cast<std::uint32_t>(a.z) == std::bit_cast<std::uint32_t>(b.z);
}

}  // namespace

const ShadowAnswer* PrimaryAhead::shadowFrom(std::size_t light, const Vec3& origin) const {
  if (light >= kPacketLights || (shadowsKnown >> light & 1u) == 0) return nullptr;
  return sameBits(shadow[light].from, origin) ? &shadow[light] : nullptr;
}

void Tracer::tracePrimaries(std::span<const Ray, kPacketSize> rays, std::uint32_t active, bool parallelView,
                            std::span<TraceResult, kPacketSize> results, TraceCounters& counters) const {
  PrimaryAhead ahead[kPacketSize];
  traceAhead(queries_, rays, active, ahead);
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    results[i] = tracePrimary(rays[i], parallelView, counters, &ahead[i]);
  }
}

void traceAhead(const SceneQueries& queries, std::span<const Ray, kPacketSize> rays, std::uint32_t active,
                std::span<PrimaryAhead, kPacketSize> ahead) {
  const Scene& scene = queries.scene();
  const Accelerator& accelerator = queries.accelerator();
  // The first query of each ray, as firstSighting makes it: the part kept by the scene's planes.
  RayPacket packet;
  std::uint32_t queried = 0;
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    packet.ray[i] = rays[i];
    ahead[i].hitKnown = true;
    const ClipInterval kept = clipRay(rays[i], scene.clipping.planes);
    if (kept.empty()) continue;
    packet.tMin[i] = kept.enter;
    packet.tMax[i] = kept.exit;
    queried |= 1u << i;
  }
  Hit hits[kPacketSize];
  const std::uint32_t hitLanes = queried == 0 ? 0u
                                 : queries.anyMeshClips()
                                     ? accelerator.intersect(packet, queried, queries.meshClipFilter(), hits)
                                     : accelerator.intersect(packet, queried, hits);
  for (std::uint32_t lanes = hitLanes; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    ahead[i].first.hit = true;
    ahead[i].first.first = hits[i];
  }
  if (scene.appearance.lights.empty()) return;

  // Where each ray's shadow rays start: from the surface it sees (as shadeLocal) or the shadow
  // catcher (as shadeShadowCatcher). Caps and misses cast none ahead.
  Vec3 from[kPacketSize], point[kPacketSize], normal[kPacketSize];
  std::uint32_t onSurface = 0, onCatcher = 0;
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    const Sighting seen = queries.firstSighting(rays[i], ahead[i].knownHit());
    if (seen.kind == Sighting::Kind::kSurface) {
      ahead[i].surface = makeSurfacePoint(scene, rays[i], seen.hit);
      ahead[i].surfaceKnown = true;
      const SurfacePoint& surface = ahead[i].surface;
      point[i] = surface.position;
      normal[i] = surface.geometricNormal;
      from[i] = offsetRayOrigin(surface.position, surface.positionError, surface.geometricNormal);
      onSurface |= 1u << i;
    } else if (seen.kind == Sighting::Kind::kShadowCatcher) {
      point[i] = rays[i].at(seen.t);
      normal[i] = scene.shadowCatcher->normal;
      from[i] = offsetRayOrigin(point[i], normal[i]);
      onCatcher |= 1u << i;
    }
  }
  const std::size_t lightCount = std::min<std::size_t>(scene.appearance.lights.size(), kPacketLights);
  RayPacket shadow;
  for (std::size_t l = 0; l < lightCount; ++l) {
    const Vec3& lightPosition = scene.appearance.lights[l].position;
    std::uint32_t traced = 0;
    for (std::uint32_t lanes = onSurface | onCatcher; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      // Only towards lights in front of the point (the shading tests the same before it asks).
      // The length is positive exactly when its square is (no square root needed to ask).
      const Vec3 toLight = lightPosition - point[i];
      if (!(dot(toLight, toLight) > 0.0f) || dot(normal[i], toLight) <= 0.0f) continue;
      if (!queries.shadowQuery(from[i], lightPosition, shadow.ray[i], shadow.tMin[i], shadow.tMax[i]))
        continue;
      traced |= 1u << i;
    }
    if (traced == 0) continue;
    // With transparent faces, the walk lightTransmission makes for a single ray, lane by lane in one
    // packet query: each lane notes the faces it crosses.
    SceneQueries::ShadowCrossings notes[kPacketSize];
    std::uint32_t blocked;
    if (!queries.anyTransparent()) {
      blocked = queries.anyMeshClips() ? accelerator.occluded(shadow, traced, queries.meshShadowClipFilter())
                                       : accelerator.occluded(shadow, traced);
    } else {
      for (std::uint32_t lanes = traced; lanes != 0; lanes &= lanes - 1)
        notes[std::countr_zero(lanes)].count = 0;
      const SceneQueries::CrossingNotes context{&queries, shadow.ray, notes};
      blocked = accelerator.occluded(shadow, traced, HitFilter{&context, &SceneQueries::notesTransparent});
    }
    for (std::uint32_t lanes = traced; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      bool through = (blocked >> i & 1u) == 0;
      int crossed = 0;
      if (queries.anyTransparent() && through) {
        through = SceneQueries::orderCrossings(notes[i]);
        crossed = through ? notes[i].count : 0;
        if (crossed > ShadowAnswer::kCrossingsKept) continue;  // left to the single ray
      }
      ShadowAnswer& answer = ahead[i].shadow[l];
      ahead[i].shadowsKnown |= 1u << l;
      answer.from = from[i];
      answer.blocked = !through;
      answer.crossingCount = static_cast<std::uint8_t>(crossed);
      std::copy_n(notes[i].hits.begin(), crossed, answer.crossings);
    }
  }
}

}  // namespace lancer
