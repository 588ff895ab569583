// The questions every integrator asks of the scene and its accelerator: what a ray sees first (a
// face, a clip plane's cap, the shadow-catcher floor or nothing), which media a surface separates,
// and how much light reaches a point from another through the transparent faces on the way.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

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

// Paths whose weight in the pixel falls below this cannot change an 8-bit value by more than half a step.
inline constexpr float kMinPathWeight = 1.0f / 512.0f;

// A transparent face on a shadow ray: where (ray parameter) and which.
struct ShadowCrossing {
  float t;
  std::uint32_t face;
};

// A ray's first closest-hit query, answered already (traced ahead in a packet).
struct KnownHit {
  bool hit = false;
  Hit first;
};

// A shadow query answered already (traced ahead in a packet) from origin `from`.
struct ShadowAnswer {
  static constexpr int kCrossingsKept = 4;
  Vec3 from;                   // the origin the query was traced from
  bool blocked;                // by an opaque face (or, with transparent faces, past the crossing budget)
  std::uint8_t crossingCount;  // scenes with transparent faces: the faces crossed,
  ShadowCrossing crossings[kCrossingsKept];  // in order along the ray
};

// What a ray sees first within the kept part of the scene, at ray parameter t.
struct Sighting {
  enum class Kind { kNothing, kShadowCatcher, kCap, kSurface } kind = Kind::kNothing;
  float t = 0;
  Hit hit;                              // the face hit (for a cap: the face the ray leaves the solid by)
  const ClipPlane* capPlane = nullptr;  // kCap
  std::uint32_t capMaterial = 0;        // kCap: the cut solid's
};

// What the per-mesh clip filters read, their context: the scene, and its on-plane tolerance (a
// square root of the bounds), computed once when the filters are set rather than per candidate hit.
struct MeshClipContext {
  const Scene* scene = nullptr;
  float onPlaneTolerance = 0;
};

class SceneQueries {
 public:
  SceneQueries(const Scene& scene, const Accelerator& accelerator);

  const Scene& scene() const { return scene_; }
  const Accelerator& accelerator() const { return accelerator_; }
  bool anyTransparent() const { return anyTransparent_; }
  bool anyMeshClips() const { return anyMeshClips_; }
  // The hits per-mesh clip planes keep: for rays that look (meshClipFilter) and for shadow rays.
  const HitFilter& meshClipFilter() const { return meshClipFilter_; }
  const HitFilter& meshShadowClipFilter() const { return meshShadowClipFilter_; }
  const EnergySplit& splitOf(std::uint32_t material) const { return splits_[material]; }
  // Whether `face` lets every ray through unbent and untinted (transparency 1, ior 1, no absorption:
  // the surface the undeformed shape's edges are drawn on), so an integrator passes it as if it
  // were not there but for the paint on it (pbrt-v4's interface material).
  bool clearFace(std::uint32_t face) const { return clear_[scene_.appearance.faceMaterial[face]] != 0; }

  // The accelerator's closest-hit and any-hit queries, seeing through the faces that per-mesh clip
  // planes remove when the scene has such planes (the plain queries otherwise).
  // Inlined into every caller: as a call they cost 1% of the trace of scenes without per-mesh planes
  // (callgrind, examples/demo.toml); inlined, 0.2%, the one test of anyMeshClips_.
  [[gnu::always_inline]] bool nearestHit(const Ray& ray, float tMin, float tMax, Hit& hit) const {
    if (!anyMeshClips_) return accelerator_.intersect(ray, tMin, tMax, hit);
    return accelerator_.intersect(ray, tMin, tMax, meshClipFilter_, hit);
  }
  [[gnu::always_inline]] bool blocked(const Ray& ray, float tMin, float tMax) const {
    if (!anyMeshClips_) return accelerator_.occluded(ray, tMin, tMax);
    return accelerator_.occluded(ray, tMin, tMax, meshShadowClipFilter_);
  }

  // What `ray` sees first; `known`: its first query, already answered. Without `withCatcher` the
  // shadow-catcher floor is not seen (rays past the first bounce of the path tracer).
  Sighting firstSighting(const Ray& ray, const KnownHit* known = nullptr, bool withCatcher = true) const;

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

  // Fraction of the light that reaches `from` from `lightPosition` (0 when blocked by an opaque
  // face; transparent faces filter it by their transparency and tint, solids also by their
  // absorption). `known`: the query, when traced ahead from `from`. With transparent faces, one
  // any-hit walk notes the faces on the way (transparentCrossings), then they are crossed in order.
  Vec3 lightTransmission(const Vec3& from, const Vec3& lightPosition, TraceCounters& counters,
                         const ShadowAnswer* known = nullptr) const;
  // The shadow ray from `from` to `lightPosition` and the interval its first query covers; false
  // when lightTransmission makes no query (the clip planes remove the whole way).
  bool shadowQuery(const Vec3& from, const Vec3& lightPosition, Ray& ray, float& tMin, float& tMax) const;

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
    const SceneQueries* queries;
    const Ray* rays;
    ShadowCrossings* lanes;
  };
  // The filter: refuses a transparent face, noting it; keeps an opaque one, which ends the walk:
  // the light is blocked whatever lies before it (and a face past the room for notes).
  static bool notesTransparent(const void* notes, const Ray& ray, std::uint32_t face, float t);
  // Puts a query's notes in order along the ray, one face per t; false when the light crosses too
  // many faces to get through.
  static bool orderCrossings(ShadowCrossings& crossings);

 private:
  // The capped plane by which `ray` entered the kept region of `face`'s mesh (the scene's planes
  // and the mesh's own), with the crossing in `tCap`; nullptr when it started inside that region or
  // entered by an uncapped plane. `kept`: the ray's interval for the scene's planes.
  const ClipPlane* capPlane(const Ray& ray, const ClipInterval& kept, std::uint32_t face, float& tCap) const;
  // Whether every corner of `face` lies on `plane` (within onPlaneTolerance_).
  bool liesOn(std::uint32_t face, const ClipPlane& plane) const;
  // The nearest hit on `ray` in the kept interval past the faces that lie on `plane`.
  bool nearestHitOffPlane(const Ray& ray, const ClipInterval& kept, const ClipPlane& plane, Hit& hit) const;
  // The transparent faces on `ray` in (tMin, tMax), in order, from one any-hit walk; false when the
  // light is blocked (an opaque face on the way, or too many faces).
  bool transparentCrossings(const Ray& ray, float tMin, float tMax, ShadowCrossings& crossings) const;
  // The light left after crossing `crossings` on `ray` (in order) up to ray parameter `end`, the
  // way starting at `start` outside every known medium.
  Vec3 transmissionThrough(const Ray& ray, float start, float end,
                           std::span<const ShadowCrossing> crossings) const;

  const Scene& scene_;
  const Accelerator& accelerator_;
  bool anyTransparent_ = false;
  bool anyMeshClips_ = false;  // some mesh has planes of its own: use the clipped queries
  // The filters' context, set when some mesh has planes of its own; shared by copies of this
  // object (an integrator moved into its variant), whose filters point at it.
  std::shared_ptr<const MeshClipContext> meshClipContext_;
  // The hits those planes keep (FaceClipSets::keeps), past a face lying in the plane a ray enters
  // its mesh's kept region by; for shadow rays, short of the plane they leave it by.
  HitFilter meshClipFilter_, meshShadowClipFilter_;
  std::vector<EnergySplit> splits_;  // per material
  std::vector<std::uint8_t> clear_;  // per material: clearFace
  float onPlaneTolerance_ = 0;       // a millionth of the scene's diagonal
};

}  // namespace lancer
