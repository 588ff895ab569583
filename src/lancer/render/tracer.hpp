// Whitted-style recursive ray tracing over a Scene and its accelerator: nearest hit, the local
// lighting model with shadow rays, then mirror reflection and refraction up to a depth.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/ray_packet.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/edge_overlay.hpp"
#include "lancer/render/feature_buffers.hpp"
#include "lancer/render/outline_edges.hpp"
#include "lancer/render/surface_point.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

struct TraceResult {
  Vec3 color{0, 0, 0};
  float alpha = 0;  // 1 when the ray hit geometry (directly or through reflections), for coverage
};

struct TraceCounters {
  std::uint64_t rays = 0;  // primary + secondary + shadow
};

// How a material shares the light leaving a point (see Tracer::trace): non-negative, and
// reflect + transmit + local = 1 per channel, so recursion cannot create energy.
struct EnergySplit {
  Vec3 reflect{0, 0, 0};
  float transmit = 0;
  Vec3 local{1, 1, 1};
  bool recursive = false;  // reflects or transmits anything
};

// A material's reflectivity and transparency as weights; scaled down together when their sum
// exceeds 1 in some channel (the scene loader rejects such materials; scenes built in code may not).
EnergySplit energySplit(const Material& material);

// The two media a surface hit separates, as material indices (SceneAppearance::kNoMaterial: outside every
// solid, or a thin sheet's surroundings), and the material the surface shows.
struct MediumCrossing {
  std::uint32_t from;   // where the ray comes from
  std::uint32_t to;     // where it goes if it passes through
  std::uint32_t shown;  // the face's own (inner) material, or the outer volume's when the ray leaves a
                        // transparent volume by an interface
};

// Transparent surfaces a shadow ray may cross before the light counts as blocked.
inline constexpr int kMaxShadowCrossings = 16;

// A transparent face on a shadow ray: where (ray parameter) and which.
struct ShadowCrossing {
  float t;
  std::uint32_t face;
};

// Shadow queries traced ahead for the first kPacketLights lights of a scene.
inline constexpr int kPacketLights = 8;

// What Tracer::tracePrimaries traced ahead, in packets, for one primary ray: its first query, and
// from the point it hit, the shadow query towards each light. The tracer takes an answer only
// for the very query it was traced for (a shadow ray from the same origin, to the bit), so the
// image is the one single rays give.
struct PrimaryAhead {
  bool hitKnown = false;  // `hit`/`firstHit` answer the ray's first closest-hit query
  bool hit = false;
  bool surfaceKnown = false;       // `surface` is makeSurfacePoint of the ray and firstHit
  std::uint32_t shadowsKnown = 0;  // bit l: shadow[l] answers the shadow query towards light l
  Hit firstHit;
  union {
    SurfacePoint surface;  // only when surfaceKnown
  };
  // Transparent faces a shadow ray crossed that a record keeps; a lane that crossed more is left
  // to its single ray (the same walk, the same answer).
  static constexpr int kCrossingsKept = 4;
  struct Shadow {
    Vec3 from;                   // the origin the query was traced from
    bool blocked;                // by an opaque face (or, with transparent faces, past the crossing budget)
    std::uint8_t crossingCount;  // scenes with transparent faces: the faces crossed,
    ShadowCrossing crossings[kCrossingsKept];  // in order along the ray
  };
  // Left unconstructed, like `surface` (a packet's worth is made per sample, and initialising them
  // all cost 5% of examples/demo.toml): only those of shadowsKnown are written and read.
  union {
    Shadow shadow[kPacketLights];
  };
  PrimaryAhead() {}

  // The answer traced ahead towards light `light` from `origin`, or nullptr.
  const Shadow* shadowFrom(std::size_t light, const Vec3& origin) const;
};

class Tracer {
 public:
  // `footprint`: the world size of a pixel along primary rays, for edges drawn in pixel widths.
  Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
         PixelFootprint footprint = {});
  // For primary rays of `camera` (which must outlive the tracer): edges get its pixel footprint,
  // and edges on outlines are drawn whole (outline_edges.hpp).
  Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
         const Camera& camera);

  // `parallelView`: the ray is an orthographic primary ray, so the viewer is at infinity along it.
  TraceResult tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters) const;
  // The primary rays of lanes `active` (up to kPacketSize neighbouring pixels or samples), each with
  // the result tracePrimary gives it, to the bit: their first hits and their shadow rays to each
  // light traced as packets (ray_packet.hpp), then each shaded on its own.
  void tracePrimaries(std::span<const Ray, kPacketSize> rays, std::uint32_t active, bool parallelView,
                      std::span<TraceResult, kPacketSize> results, TraceCounters& counters) const;
  // What a primary ray sees first, for the feature buffers (tracer_features.cpp): no lighting.
  SurfaceFeatures surfaceFeatures(const Ray& ray) const;

 private:
  // What a ray brings back: its colour, how far it went to the first thing it saw (infinity on a
  // miss: for absorption and edge widths), and how much of a pixel that thing covers (1 on geometry,
  // the shadow's density on a shadow catcher, 0 on a miss: the alpha of transparent backgrounds).
  struct TracedRay {
    Vec3 color;
    float distance;
    float coverage;
  };
  // What a ray sees first within the kept part of the scene, at ray parameter t.
  struct Sighting {
    enum class Kind { kNothing, kShadowCatcher, kCap, kSurface } kind = Kind::kNothing;
    float t = 0;
    Hit hit;                              // the face hit (for a cap: the face the ray leaves the solid by)
    const ClipPlane* capPlane = nullptr;  // kCap
    std::uint32_t capMaterial = 0;        // kCap: the cut solid's
  };
  // `pathLength` is how far the ray's origin is from the eye along the path, for edge widths.
  TracedRay trace(const Ray& ray, int depth, float pathWeight, float pathLength, bool parallelView,
                  TraceCounters& counters, const PrimaryAhead* ahead = nullptr) const;
  TraceResult tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters,
                           const PrimaryAhead* ahead) const;
  Sighting firstSighting(const Ray& ray, const PrimaryAhead* ahead = nullptr) const;
  // Traces ahead, in packets, the first queries of the rays of `active` and their first shadow queries.
  void traceAhead(std::span<const Ray, kPacketSize> rays, std::uint32_t active,
                  std::span<PrimaryAhead, kPacketSize> ahead) const;
  // The Whitted step at a surface hit `distance` along the ray: the local model, then the reflected
  // and transmitted branches.
  Vec3 shadeSurface(const Ray& ray, const Hit& hit, float distance, int depth, float pathWeight,
                    float pathLength, bool parallelView, TraceCounters& counters,
                    const PrimaryAhead* ahead) const;
  // One branch of the ray tree with its weight: traced (and absorbed by the medium it runs in) when
  // its path weight is worth it, else the point's local colour in its place.
  template <typename MakeRay>
  Vec3 traceBranch(const Vec3& weight, const Vec3& absorption, const Vec3& local, MakeRay&& makeRay,
                   int depth, float pathWeight, float pathLength, TraceCounters& counters) const;
  // The shadow-catcher floor at `point`: the background darkened by the meshes' shadows.
  Vec3 shadeShadowCatcher(const Vec3& point, TraceCounters& counters, float& coverage,
                          const PrimaryAhead* ahead) const;
  // The accelerator's closest-hit and any-hit queries, seeing through the faces that per-mesh clip
  // planes remove when the scene has such planes (the plain queries otherwise).
  bool nearestHit(const Ray& ray, float tMin, float tMax, Hit& hit) const;
  bool blocked(const Ray& ray, float tMin, float tMax) const;
  // The capped plane by which `ray` entered the kept region of `face`'s mesh (the scene's planes
  // and the mesh's own), with the crossing in `tCap`; nullptr when it started inside that region or
  // entered by an uncapped plane. `kept`: the ray's interval for the scene's planes.
  const ClipPlane* capPlane(const Ray& ray, const ClipInterval& kept, std::uint32_t face, float& tCap) const;
  // The flat face a capped clip plane shows where it cuts a solid, at ray parameter `tCap`, in the
  // solid's `material` (`face`: the face the ray would leave the solid by, for field colours).
  Vec3 shadeCap(const Ray& ray, const ClipPlane& plane, float tCap, std::uint32_t face,
                std::uint32_t material, bool parallelView, TraceCounters& counters) const;
  // What a ray meets at `face`: closed shells and volume faces are wound out of their inner volume,
  // so the side hit (`entering`: against the normal) says which volume it leaves and which it enters.
  MediumCrossing crossingAt(std::uint32_t face, bool entering) const;
  float iorOf(std::uint32_t material) const {
    return material == SceneAppearance::kNoMaterial ? 1.0f : scene_.appearance.materials[material].ior;
  }
  Vec3 absorptionOf(std::uint32_t material) const {
    return material == SceneAppearance::kNoMaterial ? Vec3{0, 0, 0}
                                                    : scene_.appearance.materials[material].absorption;
  }
  // Coverage of the hit face's drawn edges at the hit (0 when its mesh draws none).
  float edgeCoverageAt(const Ray& ray, const Hit& hit, float pathLength) const;
  // Paints the outer half of outline edges over what primary ray `ray` saw at `hitDistance`.
  void paintOutlines(const Ray& ray, float hitDistance, TraceResult& result, TraceCounters& counters,
                     const PrimaryAhead* ahead) const;
  Vec3 shadeLocal(const Ray& ray, const SurfacePoint& surface, const Material& material, bool parallelView,
                  TraceCounters& counters, const PrimaryAhead* ahead = nullptr) const;
  // Fraction of the light that reaches `from` (0 when blocked by an opaque face; transparent faces
  // filter it by their transparency and tint, solids also by their absorption).
  // `ahead`: the query, when traced ahead from `from` (tracePrimaries). With transparent faces, one
  // any-hit walk notes the faces on the way (transparentCrossings), then they are crossed in order.
  Vec3 lightTransmission(const Vec3& from, const Vec3& lightPosition, TraceCounters& counters,
                         const PrimaryAhead::Shadow* ahead = nullptr) const;
  // The transparent faces one shadow query noted (notesTransparent), as many as its filter saw: a
  // face once, but two faces at the very same t both.
  struct ShadowCrossings {
    std::array<ShadowCrossing, 2 * kMaxShadowCrossings> hits;
    int count;
  };
  // What the filter of a shadow query writes to: lane i's ray is rays[i] (a single ray: lane 0),
  // its notes lanes[i]. The queries pass the filter each ray by reference, a packet's lane as its
  // own packet.ray[i] (accel/hit_filter.hpp).
  struct CrossingNotes {
    const Tracer* tracer;
    const Ray* rays;
    ShadowCrossings* lanes;
  };
  // The filter: refuses a transparent face, noting it; keeps an opaque one, which ends the walk:
  // the light is blocked whatever lies before it (and a face past the room for notes).
  static bool notesTransparent(const void* notes, const Ray& ray, std::uint32_t face, float t);
  // Puts a query's notes in order along the ray, one face per t; false when the light crosses too
  // many faces to get through.
  static bool orderCrossings(ShadowCrossings& crossings);
  // The transparent faces on `ray` in (tMin, tMax), in order, from one any-hit walk; false when the
  // light is blocked (an opaque face on the way, or too many faces).
  bool transparentCrossings(const Ray& ray, float tMin, float tMax, ShadowCrossings& crossings) const;
  // The light left after crossing `crossings` on `ray` (in order) up to ray parameter `end`, the
  // way starting at `start` outside every known medium.
  Vec3 transmissionThrough(const Ray& ray, float start, float end,
                           std::span<const ShadowCrossing> crossings) const;
  // The shadow ray from `from` to `lightPosition` and the interval its first query covers; false
  // when lightTransmission makes no query (the clip planes remove the whole way).
  bool shadowQuery(const Vec3& from, const Vec3& lightPosition, Ray& ray, float& tMin, float& tMax) const;

  const Scene& scene_;
  const Accelerator& accelerator_;
  Vec3 background_;
  int maxDepth_;
  bool anyTransparent_ = false;
  std::vector<EnergySplit> splits_;  // per material
  PixelFootprint footprint_;
  bool linearFieldColors_ = false;        // --srgb: field colours are decoded to linear (field_shading.hpp)
  bool anyMeshClips_ = false;             // some mesh has planes of its own: use the clipped queries
  HitFilter meshClipFilter_;              // the hits those planes keep (FaceClipSets::keeps)
  std::optional<OutlineEdges> outlines_;  // with a camera, when some mesh draws its edges
};

}  // namespace lancer
