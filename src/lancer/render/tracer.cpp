#include "lancer/render/tracer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "lancer/render/field_shading.hpp"
#include "lancer/render/lighting.hpp"
#include "lancer/render/optics.hpp"
#include "lancer/render/ray_offset.hpp"
#include "lancer/render/shading.hpp"

namespace lancer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Paths whose weight in the pixel falls below this cannot change an 8-bit value by more than half a step.
constexpr float kMinPathWeight = 1.0f / 512.0f;

// Tint of the light that passes through a transparent surface: its diffuse colour at full
// brightness (white when it has none), so a blue glass casts a blue shadow.
Vec3 transmissionTint(const Material& material) {
  const float brightest = maxComponent(material.kd);
  return brightest > 0.0f ? material.kd * (1.0f / brightest) : Vec3{1, 1, 1};
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

Tracer::Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
               PixelFootprint footprint)
    : scene_(scene),
      accelerator_(accelerator),
      background_(settings.background),
      maxDepth_(settings.maxDepth),
      footprint_(footprint),
      linearFieldColors_(settings.srgb),
      anyMeshClips_(!scene.clipping.perMesh.empty()),
      meshClipFilter_{&scene.clipping.perMesh,
                      [](const void* clips, const Ray& ray, std::uint32_t face, float t) {
                        return static_cast<const FaceClipSets*>(clips)->keeps(ray, face, t);
                      }} {
  for (const Material& material : scene.appearance.materials) {
    anyTransparent_ = anyTransparent_ || material.transparency > 0;
    splits_.push_back(energySplit(material));
  }
}

Tracer::Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
               const Camera& camera)
    : Tracer(scene, accelerator, settings, camera.pixelFootprint()) {
  outlines_.emplace(scene, camera, settings.width, settings.height);
  if (outlines_->empty()) outlines_.reset();
}

// Inlined into every caller: as a call they cost 1% of the trace of scenes without per-mesh planes
// (callgrind, examples/demo.toml); inlined, 0.2%, the one test of anyMeshClips_.
[[gnu::always_inline]] inline bool Tracer::nearestHit(const Ray& ray, float tMin, float tMax,
                                                      Hit& hit) const {
  if (!anyMeshClips_) return accelerator_.intersect(ray, tMin, tMax, hit);
  return accelerator_.intersect(ray, tMin, tMax, meshClipFilter_, hit);
}

[[gnu::always_inline]] inline bool Tracer::blocked(const Ray& ray, float tMin, float tMax) const {
  if (!anyMeshClips_) return accelerator_.occluded(ray, tMin, tMax);
  return accelerator_.occluded(ray, tMin, tMax, meshClipFilter_);
}

TraceResult Tracer::tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters) const {
  return tracePrimary(ray, parallelView, counters, nullptr);
}

TraceResult Tracer::tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters,
                                 const PrimaryAhead* ahead) const {
  const TracedRay traced = trace(ray, 0, 1.0f, 0.0f, parallelView, counters, ahead);
  TraceResult result;
  result.color = traced.color;
  result.alpha = traced.coverage;
  if (outlines_ && outlines_->near(ray)) paintOutlines(ray, traced.distance, result, counters, ahead);
  return result;
}

MediumCrossing Tracer::crossingAt(std::uint32_t face, bool entering) const {
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

void Tracer::paintOutlines(const Ray& ray, float hitDistance, TraceResult& result, TraceCounters& counters,
                           const PrimaryAhead* ahead) const {
  // The face the ray hit draws its own edges; the query is repeated only near outlines.
  ++counters.rays;
  const ClipInterval kept = clipRay(ray, scene_.clipping.planes);
  Hit hit;
  if (ahead != nullptr && ahead->hitKnown) {
    if (ahead->hit) hit = ahead->firstHit;
  } else if (!kept.empty()) {
    nearestHit(ray, kept.enter, kept.exit, hit);
  }
  Vec3 color;
  const float edge = outlines_->coverage(ray, hit.face, hitDistance, footprint_, color);
  if (edge <= 0.0f) return;
  result.color = result.color * (1.0f - edge) + color * edge;
  result.alpha = std::max(result.alpha, edge);
}

bool Tracer::shadowQuery(const Vec3& from, const Vec3& lightPosition, Ray& ray, float& tMin,
                         float& tMax) const {
  ray = Ray(from, lightPosition - from);
  const ClipInterval kept = clipRay(ray, scene_.clipping.planes);
  if (kept.empty() || (!anyTransparent_ && kept.enter >= 1.0f)) return false;
  tMin = kept.enter;
  tMax = std::min(kept.exit, 1.0f);
  return true;
}

namespace {

bool sameBits(const Vec3& a, const Vec3& b) {
  return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
         std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y) &&
         std::bit_cast<std::uint32_t>(a.z) == std::bit_cast<std::uint32_t>(b.z);
}

}  // namespace

const PrimaryAhead::Shadow* PrimaryAhead::shadowFrom(std::size_t light, const Vec3& origin) const {
  if (light >= kPacketLights || (shadowsKnown >> light & 1u) == 0) return nullptr;
  return sameBits(shadow[light].from, origin) ? &shadow[light] : nullptr;
}

bool Tracer::notesTransparent(const void* context, const Ray& ray, std::uint32_t face, float t) {
  const CrossingNotes& notes = *static_cast<const CrossingNotes*>(context);
  const Tracer& tracer = *notes.tracer;
  if (tracer.anyMeshClips_ && !tracer.meshClipFilter_(ray, face, t)) return false;
  const bool leaving = dot(tracer.scene_.geometry.faceNormals[face], ray.direction) > 0;
  if (tracer.scene_.appearance.materials[tracer.crossingAt(face, !leaving).shown].transparency <= 0.0f)
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

bool Tracer::orderCrossings(ShadowCrossings& crossings) {
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

bool Tracer::transparentCrossings(const Ray& ray, float tMin, float tMax, ShadowCrossings& crossings) const {
  crossings.count = 0;
  const CrossingNotes notes{this, &ray, &crossings};
  if (accelerator_.occluded(ray, tMin, tMax, HitFilter{&notes, &Tracer::notesTransparent})) return false;
  return orderCrossings(crossings);
}

Vec3 Tracer::transmissionThrough(const Ray& ray, float start, float end,
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

Vec3 Tracer::lightTransmission(const Vec3& from, const Vec3& lightPosition, TraceCounters& counters,
                               const PrimaryAhead::Shadow* ahead) const {
  ++counters.rays;
  // Traced ahead from this very origin (tracePrimaries): the query was made, and answered.
  if (ahead != nullptr && ahead->blocked) return {0, 0, 0};
  Ray ray;
  float tMin, tMax;
  if (!anyTransparent_) {
    if (ahead != nullptr) return {1, 1, 1};
    if (!shadowQuery(from, lightPosition, ray, tMin, tMax)) return {1, 1, 1};
    return blocked(ray, tMin, tMax) ? Vec3{0, 0, 0} : Vec3{1, 1, 1};
  }
  // Every face on the way in one walk: an opaque one blocks the light, transparent ones filter it.
  if (!shadowQuery(from, lightPosition, ray, tMin, tMax)) return {1, 1, 1};
  if (ahead != nullptr)
    return transmissionThrough(ray, std::max(tMin, 0.0f), tMax, {ahead->crossings, ahead->crossingCount});
  ShadowCrossings crossings;
  if (!transparentCrossings(ray, tMin, tMax, crossings)) return {0, 0, 0};
  return transmissionThrough(ray, std::max(tMin, 0.0f), tMax,
                             {crossings.hits.data(), static_cast<std::size_t>(crossings.count)});
}

Vec3 Tracer::shadeLocal(const Ray& ray, const SurfacePoint& surface, const Material& material,
                        bool parallelView, TraceCounters& counters, const PrimaryAhead* ahead) const {
  // A field-coloured face (color_by) shows the map's colour as ka and kd; ks and shininess stay.
  Vec3 fieldColor;
  const bool colored = fieldColorAt(scene_, surface, linearFieldColors_, fieldColor);
  const Vec3& kd = colored ? fieldColor : material.kd;
  Vec3 color = scene_.appearance.ambient * (colored ? fieldColor : material.ka);
  const Vec3 toViewer = normalize(-ray.direction);
  const Vec3 shadowOrigin = offsetRayOrigin(surface.position, surface.positionError, surface.geometricNormal);
  const bool perCorner =
      !surface.isCap && scene_.appearance.faceShading[surface.face] == ShadingMode::Gouraud;
  for (std::size_t l = 0; l < scene_.appearance.lights.size(); ++l) {
    const SceneLight& light = scene_.appearance.lights[l];
    const Vec3 toLight = light.position - surface.position;
    const float distance = length(toLight);
    if (!(distance > 0.0f)) continue;
    const Vec3 lightDirection = toLight * (1.0f / distance);
    // A light behind the geometric surface is blocked by the surface itself.
    if (dot(surface.geometricNormal, lightDirection) <= 0.0f) continue;
    // lightResponse's own first case, inlined: all but Gouraud faces light the point itself.
    const Vec3 contribution = perCorner ? lightResponse(scene_, surface, material, kd, light, ray,
                                                        parallelView, toViewer, lightDirection, distance)
                                        : directLighting(material, kd, light, surface.shadingNormal, toViewer,
                                                         lightDirection, distance);
    if (maxComponent(contribution) <= 0.0f) continue;
    color +=
        contribution * lightTransmission(shadowOrigin, light.position, counters,
                                         ahead != nullptr ? ahead->shadowFrom(l, shadowOrigin) : nullptr);
  }
  return color;
}

Vec3 Tracer::shadeShadowCatcher(const Vec3& point, TraceCounters& counters, float& coverage,
                                const PrimaryAhead* ahead) const {
  // The share of the light the floor would get that the meshes let through, per channel: ambient
  // plus the lights' diffuse irradiance with shadows, over the same without them.
  const Vec3& normal = scene_.shadowCatcher->normal;
  Vec3 lit = scene_.appearance.ambient, shadowed = scene_.appearance.ambient;
  const Vec3 shadowOrigin = offsetRayOrigin(point, normal);
  for (std::size_t l = 0; l < scene_.appearance.lights.size(); ++l) {
    const SceneLight& light = scene_.appearance.lights[l];
    const Vec3 toLight = light.position - point;
    const float distance = length(toLight);
    const float cosTheta = distance > 0.0f ? dot(normal, toLight) / distance : 0.0f;
    if (cosTheta <= 0.0f) continue;
    const Vec3 irradiance = light.intensity * (cosTheta * lightAttenuation(light, distance));
    lit += irradiance;
    shadowed +=
        irradiance * lightTransmission(shadowOrigin, light.position, counters,
                                       ahead != nullptr ? ahead->shadowFrom(l, shadowOrigin) : nullptr);
  }
  auto ratio = [](float s, float l) { return l > 0.0f ? std::clamp(s / l, 0.0f, 1.0f) : 1.0f; };
  const Vec3 kept{ratio(shadowed.x, lit.x), ratio(shadowed.y, lit.y), ratio(shadowed.z, lit.z)};
  // Over a transparent background the shadow is black with the darkening as its opacity.
  coverage = std::max(coverage, 1.0f - (kept.x + kept.y + kept.z) / 3.0f);
  return background_ * kept;
}

const ClipPlane* Tracer::capPlane(const Ray& ray, const ClipInterval& kept, std::uint32_t face,
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

Vec3 Tracer::shadeCap(const Ray& ray, const ClipPlane& plane, float tCap, std::uint32_t face,
                      std::uint32_t material, bool parallelView, TraceCounters& counters) const {
  SurfacePoint cap{};
  cap.face = face;
  cap.position = ray.at(tCap);
  cap.positionError = rayPointError(ray.origin, ray.direction, tCap);
  // The ray came from the removed side, where the plane's normal points: the cap faces it.
  cap.geometricNormal = cap.shadingNormal = plane.normal;
  cap.normalSign = 1.0f;
  cap.isCap = true;
  // A field-coloured shell colours its cap with the mean of the face the ray leaves by.
  const int corners = scene_.geometry.faces[face].cornerCount();
  for (int c = 0; c < corners; ++c) cap.cornerWeight[c] = 1.0f / static_cast<float>(corners);
  return shadeLocal(ray, cap, scene_.appearance.materials[material], parallelView, counters);
}

float Tracer::edgeCoverageAt(const Ray& ray, const Hit& hit, float pathLength) const {
  if (!scene_.edges) return 0.0f;
  const EdgeOverlay& overlay = *scene_.edges;
  const std::uint16_t style = overlay.faceEdgeStyle[hit.face];
  if (style == 0) return 0.0f;
  const MeshFace& face = scene_.geometry.faces[hit.face];
  Vec3 corners[4];
  for (int c = 0; c < face.cornerCount(); ++c) corners[c] = scene_.geometry.positions[face.vertex[c]];
  const float directionLength = length(ray.direction);
  const float pixelSize = footprint_.at(pathLength + hit.t * directionLength);
  return edgeCoverage(ray.origin, ray.direction * (1.0f / directionLength), corners, face.cornerCount(),
                      overlay.faceEdgeMask[hit.face], overlay.faceLineCorners[hit.face], pixelSize,
                      overlay.styles[style].widthPixels);
}

Tracer::Sighting Tracer::firstSighting(const Ray& ray, const PrimaryAhead* ahead) const {
  Sighting seen;
  // Cut views: only the part of the ray on the kept side of every scene clip plane can hit
  // anything; a mesh's own planes are seen through by the query itself.
  const ClipInterval kept = clipRay(ray, scene_.clipping.planes);
  bool hitMesh;
  if (ahead != nullptr && ahead->hitKnown) {
    hitMesh = ahead->hit;
    if (hitMesh) seen.hit = ahead->firstHit;
  } else {
    hitMesh = !kept.empty() && nearestHit(ray, kept.enter, kept.exit, seen.hit);
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
  if (const std::optional<ShadowCatcher>& catcher = scene_.shadowCatcher) {
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

// The ray tree, depth first. At each hit the light leaving towards the viewer is
//   local * split.local + reflected * reflectWeight + transmitted * transmitWeight,
// where reflectWeight + transmitWeight = split.reflect + split.transmit (Fresnel and total internal
// reflection only move weight from transmission to reflection) and split.local = 1 - both. A branch
// that is not traced (depth limit, or a path weight below 1/512) takes the local colour instead, so
// every node is a weighted mean of non-negative terms with weights summing to 1: light can only be
// lost (absorption), never created, and depth 0 is exactly the local model.
Tracer::TracedRay Tracer::trace(const Ray& ray, int depth, float pathWeight, float pathLength,
                                bool parallelView, TraceCounters& counters, const PrimaryAhead* ahead) const {
  ++counters.rays;
  const Sighting seen = firstSighting(ray, ahead);
  const float distance = seen.t * length(ray.direction);
  switch (seen.kind) {
    case Sighting::Kind::kNothing:
      return {background_, kInfinity, 0.0f};
    case Sighting::Kind::kShadowCatcher: {
      float coverage = 0;
      const Vec3 color = shadeShadowCatcher(ray.at(seen.t), counters, coverage, ahead);
      return {color, distance, coverage};
    }
    case Sighting::Kind::kCap:
      return {shadeCap(ray, *seen.capPlane, seen.t, seen.hit.face, seen.capMaterial, parallelView, counters),
              distance, 1.0f};
    case Sighting::Kind::kSurface:
      break;
  }
  return {shadeSurface(ray, seen.hit, distance, depth, pathWeight, pathLength, parallelView, counters, ahead),
          distance, 1.0f};
}

Vec3 Tracer::shadeSurface(const Ray& ray, const Hit& hit, float distance, int depth, float pathWeight,
                          float pathLength, bool parallelView, TraceCounters& counters,
                          const PrimaryAhead* ahead) const {
  // Edges are paint on the surface: fully covered pixels need no shading, partial ones blend.
  const float edge = edgeCoverageAt(ray, hit, pathLength);
  const Vec3 edgeColor =
      edge > 0.0f ? scene_.edges->styles[scene_.edges->faceEdgeStyle[hit.face]].color : Vec3{};
  if (edge >= 1.0f) return edgeColor;
  auto withEdge = [&](const Vec3& color) {
    return edge > 0.0f ? color * (1.0f - edge) + edgeColor * edge : color;
  };
  SurfacePoint made;
  if (ahead == nullptr || !ahead->surfaceKnown) made = makeSurfacePoint(scene_, ray, hit);
  const SurfacePoint& surface = ahead != nullptr && ahead->surfaceKnown ? ahead->surface : made;
  // Closed shells and volumes face out of their material, so the side hit says whether the ray enters.
  const MediumCrossing media = crossingAt(hit.face, surface.normalSign > 0.0f);
  const Material& material = scene_.appearance.materials[media.shown];
  const EnergySplit& split = splits_[media.shown];
  const Vec3 local = shadeLocal(ray, surface, material, parallelView, counters, ahead);
  if (depth >= maxDepth_ || !split.recursive) return withEdge(local);

  const Vec3 direction = normalize(ray.direction);
  // Glass into water bends by n_glass / n_water; an open surface is a thin sheet.
  const InterfaceSplit weights =
      splitAtInterface(direction, surface.shadingNormal, surface.geometricNormal,
                       scene_.geometry.faceBoundsSolid[hit.face] != 0, iorOf(media.from) / iorOf(media.to),
                       material.fresnel, 1.0f / material.ior, split.reflect, split.transmit);
  const float branchLength = pathLength + distance;
  Vec3 color = local * split.local;
  // Reflected: the ray stays in the medium it came from (Beer-Lambert inside a solid).
  color += traceBranch(
      weights.reflect, absorptionOf(media.from), local,
      [&] {
        Vec3 reflected = reflect(direction, surface.shadingNormal);
        if (dot(reflected, surface.geometricNormal) <= 0.0f)
          reflected = reflect(direction, surface.geometricNormal);
        return Ray(offsetRayOrigin(surface.position, surface.geometricNormal), reflected);
      },
      depth, pathWeight, branchLength, counters);
  // Transmitted: into the medium beyond, absorbed along the segment inside it.
  color += traceBranch(
      Vec3{1, 1, 1} * weights.transmit, absorptionOf(media.to), local,
      [&] {
        return Ray(offsetRayOrigin(surface.position, -surface.geometricNormal), weights.transmittedDirection);
      },
      depth, pathWeight, branchLength, counters);
  return withEdge(color);
}

template <typename MakeRay>
Vec3 Tracer::traceBranch(const Vec3& weight, const Vec3& absorption, const Vec3& local, MakeRay&& makeRay,
                         int depth, float pathWeight, float pathLength, TraceCounters& counters) const {
  const float branchWeight = pathWeight * maxComponent(weight);
  if (branchWeight < kMinPathWeight) return local * weight;
  const TracedRay traced = trace(makeRay(), depth + 1, branchWeight, pathLength, false, counters);
  Vec3 radiance = traced.color;
  if (maxComponent(absorption) > 0.0f)
    radiance *= std::isfinite(traced.distance) ? beerLambert(absorption, traced.distance) : Vec3{0, 0, 0};
  return radiance * weight;
}

}  // namespace lancer
