#include "lancer/render/scene_queries.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "lancer/render/optics.hpp"

namespace lancer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Tint of the light that passes through a transparent surface: its diffuse colour at full
// brightness (white when it has none), so a blue glass casts a blue shadow.
Vec3 transmissionTint(const Material& material) {
  const float brightest = maxComponent(material.kd);
  return brightest > 0.0f ? material.kd * (1.0f / brightest) : Vec3{1, 1, 1};
}

// A millionth of the scene's diagonal: a face whose corners are all this near a clip plane lies in it.
float onPlaneTolerance(const Scene& scene) {
  return scene.geometry.bounds.empty() ? 0.0f : 1e-6f * length(scene.geometry.bounds.extent());
}

bool liesOnPlane(const Scene& scene, std::uint32_t face, const ClipPlane& plane, float tolerance) {
  for (const std::uint32_t v : scene.geometry.faces[face].vertex) {
    if (v == kNoVertex) break;
    if (std::abs(dot(scene.geometry.positions[v] - plane.point, plane.normal)) > tolerance) return false;
  }
  return true;
}

// The hit filters of per-mesh planes (context: a MeshClipContext). A mesh's own planes treat a face
// lying in one of them as the scene's planes do (SceneQueries::firstSighting, shadowQuery): a ray
// never meets it in the plane it enters the mesh's kept region by, and a shadow ray stops the on-plane
// tolerance short of the plane it leaves that region by. Otherwise FaceClipSets::keeps.
// The part of `ray` that the own planes of `face`'s mesh keep (`kept`); null when that mesh has none.
const FaceClipRange* keptByOwnPlanes(const Scene& scene, const Ray& ray, std::uint32_t face,
                                     ClipInterval& kept) {
  const FaceClipSets& clips = scene.clipping.perMesh;
  const FaceClipRange* range = clips.rangeOf(face);
  if (range) kept = clipRay(ray, clips.planesOf(*range));
  return range;
}

bool keepsOnOwnPlanes(const void* context, const Ray& ray, std::uint32_t face, float t) {
  const auto& [scene, tolerance] = *static_cast<const MeshClipContext*>(context);
  ClipInterval kept;
  const FaceClipRange* range = keptByOwnPlanes(*scene, ray, face, kept);
  if (!range) return true;
  if (!(t > kept.enter && t < kept.exit)) return false;
  if (kept.enterPlane < 0) return true;
  const ClipPlane& entered =
      scene->clipping.perMesh.planes[range->planeBegin + static_cast<std::size_t>(kept.enterPlane)];
  return !liesOnPlane(*scene, face, entered, tolerance);
}

bool keepsOnOwnPlanesForLight(const void* context, const Ray& ray, std::uint32_t face, float t) {
  const auto& [scene, tolerance] = *static_cast<const MeshClipContext*>(context);
  ClipInterval kept;
  if (!keptByOwnPlanes(*scene, ray, face, kept)) return true;
  if (!(t > kept.enter && t < kept.exit)) return false;
  return !(kept.exitRate > 0.0f && t >= kept.exit - tolerance / kept.exitRate);
}

}  // namespace

EnergySplit energySplit(const Material& material) {
  EnergySplit split;
  split.reflect = max(material.reflectivity, Vec3{0, 0, 0});
  split.transmit = std::max(material.transparency, 0.0f);
  const float largest = maxComponent(split.reflect + Vec3{1, 1, 1} * split.transmit);
  if (largest > 1.0f) {
    split.reflect = split.reflect * (1.0f / largest);
    split.transmit /= largest;
  }
  split.local = max(Vec3{1, 1, 1} - split.reflect - Vec3{1, 1, 1} * split.transmit, Vec3{0, 0, 0});
  split.recursive = maxComponent(split.reflect) > 0.0f || split.transmit > 0.0f;
  return split;
}

SceneQueries::SceneQueries(const Scene& scene, const Accelerator& accelerator)
    : scene_(scene),
      accelerator_(accelerator),
      anyMeshClips_(!scene.clipping.perMesh.empty()),
      meshClipContext_(anyMeshClips_ ? std::make_shared<const MeshClipContext>(
                                           MeshClipContext{&scene, onPlaneTolerance(scene)})
                                     : nullptr),
      meshClipFilter_{meshClipContext_.get(), &keepsOnOwnPlanes},
      meshShadowClipFilter_{meshClipContext_.get(), &keepsOnOwnPlanesForLight} {
  for (const Material& material : scene.appearance.materials) {
    anyTransparent_ = anyTransparent_ || material.transparency > 0;
    splits_.push_back(energySplit(material));
    const bool clear = splits_.back().transmit >= 1.0f && material.ior == 1.0f &&
                       maxComponent(material.absorption) <= 0.0f && maxComponent(material.emission) <= 0.0f &&
                       transmissionTint(material) == Vec3{1, 1, 1};
    clear_.push_back(clear ? 1 : 0);
  }
  onPlaneTolerance_ = onPlaneTolerance(scene);
}

MediumCrossing SceneQueries::crossingAt(std::uint32_t face, bool entering) const {
  const std::uint32_t inner = scene_.appearance.faceMaterial[face];
  if (!scene_.geometry.faceBoundsSolid[face])
    return {SceneAppearance::kNoMaterial, SceneAppearance::kNoMaterial, inner};
  const std::uint32_t outer = scene_.appearance.faceOuterMaterial.empty()
                                  ? SceneAppearance::kNoMaterial
                                  : scene_.appearance.faceOuterMaterial[face];
  if (entering) return {outer, inner, inner};
  // Leaving by an interface: out of a transparent volume the ray sees the next volume's surface;
  // inside an opaque one (only a cut view without caps gets there) its own wall, as on the skin.
  const bool seesOuter =
      outer != SceneAppearance::kNoMaterial && scene_.appearance.materials[inner].transparency > 0.0f;
  return {inner, outer, seesOuter ? outer : inner};
}

bool SceneQueries::shadowQuery(const Vec3& from, const Vec3& lightPosition, Ray& ray, float& tMin,
                               float& tMax) const {
  ray = Ray(from, lightPosition - from);
  const ClipInterval kept = clipRay(ray, scene_.clipping.planes);
  if (kept.empty() || (!anyTransparent_ && kept.enter >= 1.0f)) return false;
  tMin = kept.enter;
  tMax = std::min(kept.exit, 1.0f);
  // A way out through a plane stops short of it by the on-plane tolerance: a face lying in the plane
  // (a model's flat side where the cut passes) would block the light or not by rounding, speckling
  // the shadows it casts from the part cut away.
  if (kept.exit <= 1.0f && kept.exitRate > 0.0f)
    tMax = std::max(tMin, tMax - onPlaneTolerance_ / kept.exitRate);
  return true;
}

bool SceneQueries::notesTransparent(const void* context, const Ray& ray, std::uint32_t face, float t) {
  const CrossingNotes& notes = *static_cast<const CrossingNotes*>(context);
  const SceneQueries& queries = *notes.queries;
  if (queries.anyMeshClips_ && !queries.meshShadowClipFilter_(ray, face, t)) return false;
  const bool leaving = dot(queries.scene_.geometry.faceNormals[face], ray.direction) > 0;
  if (queries.scene_.appearance.materials[queries.crossingAt(face, !leaving).shown].transparency <= 0.0f)
    return true;
  // The walk visits every cell of the way when it keeps nothing, so it sees every hit, with the t
  // the closest-hit test computes. A triangle cut into several leaves may be seen more than once,
  // and a quad's two halves are one face: a face is noted once.
  ShadowCrossings& noted = notes.lanes[&ray - notes.rays];
  for (int i = 0; i < noted.count; ++i) {
    if (noted.hits[static_cast<std::size_t>(i)].face == face) return false;
  }
  if (noted.count == static_cast<int>(noted.hits.size())) return true;  // far more faces than the budget
  noted.hits[static_cast<std::size_t>(noted.count++)] = {t, face};
  return false;
}

bool SceneQueries::orderCrossings(ShadowCrossings& crossings) {
  // Along the ray, ties to the lower face as the closest-hit query breaks them; of faces at the very
  // same t (a ray through the edge two of them share: both compute the same t to the bit) the
  // light crosses one, as a query restarted past the first would not meet the other.
  const auto first = crossings.hits.begin(), last = first + crossings.count;
  std::sort(first, last, [](const ShadowCrossing& a, const ShadowCrossing& b) {
    return closerThan(a.t, a.face, Hit{b.t, b.face});
  });
  crossings.count = static_cast<int>(
      std::unique(first, last, [](const ShadowCrossing& a, const ShadowCrossing& b) { return a.t == b.t; }) -
      first);
  return crossings.count < kMaxShadowCrossings;
}

bool SceneQueries::transparentCrossings(const Ray& ray, float tMin, float tMax,
                                        ShadowCrossings& crossings) const {
  crossings.count = 0;
  const CrossingNotes notes{this, &ray, &crossings};
  if (accelerator_.occluded(ray, tMin, tMax, HitFilter{&notes, &SceneQueries::notesTransparent}))
    return false;
  return orderCrossings(crossings);
}

Vec3 SceneQueries::transmissionThrough(const Ray& ray, float start, float end,
                                       std::span<const ShadowCrossing> crossings) const {
  // Inside a solid the light is also absorbed (Beer-Lambert). Each stretch of the way is in the
  // medium its far end leaves (the side of the face crossed says which), so a ray that starts
  // inside a solid is absorbed from its start; past the last face, in the medium that face let it
  // into.
  constexpr std::uint32_t kUnknown = SceneAppearance::kNoMaterial - 1;
  std::uint32_t medium = kUnknown;
  Vec3 transmission{1, 1, 1};
  const float scale = length(ray.direction);
  for (const ShadowCrossing& crossing : crossings) {
    const bool leaving = dot(scene_.geometry.faceNormals[crossing.face], ray.direction) > 0;
    const MediumCrossing media = crossingAt(crossing.face, !leaving);
    const Material& material = scene_.appearance.materials[media.shown];
    const bool bounds = scene_.geometry.faceBoundsSolid[crossing.face];
    if (bounds) medium = media.from;
    if (medium != kUnknown) {
      const Vec3 absorption = absorptionOf(medium);
      if (maxComponent(absorption) > 0.0f)
        transmission *= beerLambert(absorption, std::max(crossing.t - start, 0.0f) * scale);
    }
    if (bounds) medium = media.to;
    transmission *= transmissionTint(material) * splits_[media.shown].transmit;
    if (maxComponent(transmission) < kMinPathWeight) return {0, 0, 0};
    start = crossing.t;
  }
  if (medium != kUnknown && start < end)
    transmission *= beerLambert(absorptionOf(medium), (end - start) * scale);
  return transmission;
}

Vec3 SceneQueries::lightTransmission(const Vec3& from, const Vec3& lightPosition, TraceCounters& counters,
                                     const ShadowAnswer* known) const {
  ++counters.rays;
  // Traced ahead from this very origin (a packet): the query was made, and answered.
  if (known != nullptr && known->blocked) return {0, 0, 0};
  Ray ray;
  float tMin, tMax;
  if (!anyTransparent_) {
    if (known != nullptr) return {1, 1, 1};
    if (!shadowQuery(from, lightPosition, ray, tMin, tMax)) return {1, 1, 1};
    return blocked(ray, tMin, tMax) ? Vec3{0, 0, 0} : Vec3{1, 1, 1};
  }
  // Every face on the way in one walk: an opaque one blocks the light, transparent ones filter it.
  if (!shadowQuery(from, lightPosition, ray, tMin, tMax)) return {1, 1, 1};
  if (known != nullptr)
    return transmissionThrough(ray, std::max(tMin, 0.0f), tMax, {known->crossings, known->crossingCount});
  ShadowCrossings crossings;
  if (!transparentCrossings(ray, tMin, tMax, crossings)) return {0, 0, 0};
  return transmissionThrough(ray, std::max(tMin, 0.0f), tMax,
                             {crossings.hits.data(), static_cast<std::size_t>(crossings.count)});
}

const ClipPlane* SceneQueries::capPlane(const Ray& ray, const ClipInterval& kept, std::uint32_t face,
                                        float& tCap) const {
  // The mesh's own planes and the scene's together keep a convex region, entered at the later of
  // the two entries, by that entry's plane.
  if (const FaceClipRange* range = anyMeshClips_ ? scene_.clipping.perMesh.rangeOf(face) : nullptr) {
    const ClipInterval own = clipRay(ray, scene_.clipping.perMesh.planesOf(*range));
    if (own.enterPlane >= 0 && own.enter > kept.enter) {
      const std::size_t plane = range->planeBegin + static_cast<std::size_t>(own.enterPlane);
      if (!scene_.clipping.perMesh.caps[plane]) return nullptr;
      tCap = own.enter;
      return &scene_.clipping.perMesh.planes[plane];
    }
  }
  if (kept.enterPlane < 0 || !scene_.clipping.caps[static_cast<std::size_t>(kept.enterPlane)]) return nullptr;
  tCap = kept.enter;
  return &scene_.clipping.planes[static_cast<std::size_t>(kept.enterPlane)];
}

bool SceneQueries::liesOn(std::uint32_t face, const ClipPlane& plane) const {
  return liesOnPlane(scene_, face, plane, onPlaneTolerance_);
}

bool SceneQueries::nearestHitOffPlane(const Ray& ray, const ClipInterval& kept, const ClipPlane& plane,
                                      Hit& hit) const {
  struct Context {
    const SceneQueries* queries;
    const ClipPlane* plane;
  } context{this, &plane};
  const HitFilter offPlane{&context, [](const void* c, const Ray& r, std::uint32_t face, float t) {
                             const Context& own = *static_cast<const Context*>(c);
                             if (own.queries->anyMeshClips_ && !own.queries->meshClipFilter_(r, face, t))
                               return false;
                             return !own.queries->liesOn(face, *own.plane);
                           }};
  return accelerator_.intersect(ray, kept.enter, kept.exit, offPlane, hit);
}

Sighting SceneQueries::firstSighting(const Ray& ray, const KnownHit* known, bool withCatcher) const {
  Sighting seen;
  // Cut views: only the part of the ray on the kept side of every scene clip plane can hit
  // anything; a mesh's own planes are seen through by the query itself.
  const ClipInterval kept = clipRay(ray, scene_.clipping.planes);
  bool hitMesh;
  if (known != nullptr) {
    hitMesh = known->hit;
    if (hitMesh) seen.hit = known->first;
  } else {
    hitMesh = !kept.empty() && nearestHit(ray, kept.enter, kept.exit, seen.hit);
  }
  // A face lying in the plane the ray enters the kept part by (a model's flat side where the cut
  // passes) is met or missed by the rounding of two ways to the same t: met from behind it made a
  // cap of no thickness, speckles over whatever lies beyond. It is never met: the ray goes on as if
  // it had missed it, to what is past it, or into the solid behind it and out to its cap.
  if (hitMesh && kept.enterPlane >= 0) {
    const ClipPlane& plane = scene_.clipping.planes[static_cast<std::size_t>(kept.enterPlane)];
    if (liesOn(seen.hit.face, plane)) hitMesh = nearestHitOffPlane(ray, kept, plane, seen.hit);
  }
  if (hitMesh) {
    seen.kind = Sighting::Kind::kSurface;
    seen.t = seen.hit.t;
    // A ray that crosses a capped plane and then leaves a solid was inside it at the plane: it sees
    // the cut face (the cap) there, flat, in the solid's material: the face's own when the ray
    // leaves through its back, the outer volume's when it meets an interface from the front. Only
    // the hit mesh's planes matter: the ray met no kept face of that mesh since the crossing.
    if ((kept.enterPlane >= 0 || anyMeshClips_) && scene_.geometry.faceBoundsSolid[seen.hit.face]) {
      const bool entering = dot(scene_.geometry.faceNormals[seen.hit.face], ray.direction) < 0.0f;
      const std::uint32_t solid = crossingAt(seen.hit.face, entering).from;
      float tCap = 0;
      if (solid != SceneAppearance::kNoMaterial) seen.capPlane = capPlane(ray, kept, seen.hit.face, tCap);
      if (seen.capPlane) {
        seen.kind = Sighting::Kind::kCap;
        seen.t = tCap;
        seen.capMaterial = solid;
      }
    }
  }
  const std::optional<ShadowCatcher>& catcher = scene_.shadowCatcher;
  if (withCatcher && catcher) {
    // The catcher is a plane seen from above, in front of what the ray sees (a cap or a face) and
    // inside the kept part.
    const float rate = dot(ray.direction, catcher->normal);
    const float t = rate < 0.0f ? (catcher->offset - dot(ray.origin, catcher->normal)) / rate : kInfinity;
    if (t > kept.enter && t < kept.exit && t < (hitMesh ? seen.t : kInfinity)) {
      seen.kind = Sighting::Kind::kShadowCatcher;
      seen.t = t;
    }
  }
  return seen;
}

}  // namespace lancer
