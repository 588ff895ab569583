// Internal to the Whitted tracer's packets (tracer_packets.cpp): what a packet of primary rays
// traced ahead of the shading, ray by ray, so that each ray's own queries find their answers.
#pragma once

#include <cstdint>
#include <span>

#include "lancer/accel/ray_packet.hpp"
#include "lancer/render/scene_queries.hpp"
#include "lancer/render/surface_point.hpp"

namespace lancer {

// Shadow queries traced ahead for the first kPacketLights lights of a scene.
inline constexpr int kPacketLights = 8;

// What was traced ahead, in packets, for one primary ray: its first query, and from the point it
// hit, the shadow query towards each light. The tracer takes an answer only for the very query it
// was traced for (a shadow ray from the same origin, to the bit), so the image is the one single
// rays give.
struct PrimaryAhead {
  bool hitKnown = false;           // `first` answers the ray's first closest-hit query
  bool surfaceKnown = false;       // `surface` is makeSurfacePoint of the ray and first.first
  std::uint32_t shadowsKnown = 0;  // bit l: shadow[l] answers the shadow query towards light l
  KnownHit first;
  union {
    SurfacePoint surface;  // only when surfaceKnown
  };
  // Left unconstructed, like `surface` (a packet's worth is made per sample, and initialising them
  // all cost 5% of examples/demo.toml): only those of shadowsKnown are written and read. A lane
  // that crossed more transparent faces than an answer keeps is left to its single ray (the same
  // walk, the same answer).
  union {
    ShadowAnswer shadow[kPacketLights];
  };
  PrimaryAhead() {}

  const KnownHit* knownHit() const { return hitKnown ? &first : nullptr; }
  // The answer traced ahead towards light `light` from `origin`, or nullptr.
  const ShadowAnswer* shadowFrom(std::size_t light, const Vec3& origin) const;
};

// Traces ahead, in packets, the first queries of the rays of `active` and their first shadow queries.
void traceAhead(const SceneQueries& queries, std::span<const Ray, kPacketSize> rays, std::uint32_t active,
                std::span<PrimaryAhead, kPacketSize> ahead);

}  // namespace lancer
