#include "lancer/render/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/render/field_shading.hpp"
#include "lancer/render/isoline_paint.hpp"
#include "lancer/render/lighting.hpp"
#include "lancer/render/optics.hpp"
#include "lancer/render/primary_ahead.hpp"
#include "lancer/render/ray_offset.hpp"
#include "lancer/render/shading.hpp"

namespace lancer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

Tracer::Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
               PixelFootprint footprint)
    : scene_(scene),
      queries_(scene, accelerator),
      paint_(scene, footprint),
      background_(settings.background),
      maxDepth_(settings.maxDepth),
      linearFieldColors_(settings.srgb) {}

Tracer::Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
               const Camera& camera)
    : scene_(scene),
      queries_(scene, accelerator),
      paint_(scene, camera, settings.width, settings.height),
      background_(settings.background),
      maxDepth_(settings.maxDepth),
      linearFieldColors_(settings.srgb),
      parallelView_(camera.projection() == Projection::Orthographic) {}

TraceResult Tracer::tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters) const {
  return tracePrimary(ray, parallelView, counters, nullptr);
}

TraceResult Tracer::tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters,
                                 const PrimaryAhead* ahead) const {
  const TracedRay traced = trace(ray, RayPath{0, 1.0f, 0.0f, parallelView, &counters, ahead});
  TraceResult result;
  result.color = traced.color;
  result.alpha = traced.coverage;
  paint_.paintOutlines(queries_, ray, traced.distance, result, counters,
                       ahead != nullptr ? ahead->knownHit() : nullptr);
  return result;
}

Vec3 Tracer::shadeLocal(const Ray& ray, const SurfacePoint& surface, const Material& material,
                        bool parallelView, TraceCounters& counters, const PrimaryAhead* ahead) const {
  // A field-coloured face (color_by) shows the map's colour as ka and kd; ks and shininess stay.
  Vec3 fieldColor;
  const bool colored = fieldColorAt(scene_, surface, linearFieldColors_, fieldColor);
  const Vec3& kd = colored ? fieldColor : material.kd;
  if (unlitFace(scene_, surface.face)) return kd;
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
    color += contribution *
             queries_.lightTransmission(shadowOrigin, light.position, counters,
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
    shadowed += irradiance *
                queries_.lightTransmission(shadowOrigin, light.position, counters,
                                           ahead != nullptr ? ahead->shadowFrom(l, shadowOrigin) : nullptr);
  }
  auto ratio = [](float s, float l) { return l > 0.0f ? std::clamp(s / l, 0.0f, 1.0f) : 1.0f; };
  const Vec3 kept{ratio(shadowed.x, lit.x), ratio(shadowed.y, lit.y), ratio(shadowed.z, lit.z)};
  // Over a transparent background the shadow is black with the darkening as its opacity.
  coverage = std::max(coverage, 1.0f - (kept.x + kept.y + kept.z) / 3.0f);
  return background_ * kept;
}

Vec3 Tracer::shadeCap(const Ray& ray, const ClipPlane& plane, float tCap, std::uint32_t face,
                      std::uint32_t material, bool parallelView, TraceCounters& counters) const {
  const SurfacePoint cap = makeCapPoint(scene_, ray, plane, tCap, face);
  return shadeLocal(ray, cap, scene_.appearance.materials[material], parallelView, counters);
}

// The ray tree, depth first. At each hit the light leaving towards the viewer is
//   local * split.local + reflected * reflectWeight + transmitted * transmitWeight,
// where reflectWeight + transmitWeight = split.reflect + split.transmit (Fresnel and total internal
// reflection only move weight from transmission to reflection) and split.local = 1 - both. A branch
// that is not traced (depth limit, or a path weight below 1/512) takes the local colour instead, so
// every node is a weighted mean of non-negative terms with weights summing to 1: light can only be
// lost (absorption), never created, and depth 0 is exactly the local model.
Tracer::TracedRay Tracer::trace(const Ray& ray, const RayPath& path) const {
  TraceCounters& counters = *path.counters;
  ++counters.rays;
  const Sighting seen = queries_.firstSighting(ray, path.ahead != nullptr ? path.ahead->knownHit() : nullptr);
  const float distance = seen.t * length(ray.direction);
  switch (seen.kind) {
    case Sighting::Kind::kNothing:
      return {background_, kInfinity, 0.0f};
    case Sighting::Kind::kShadowCatcher: {
      float coverage = 0;
      const Vec3 color = shadeShadowCatcher(ray.at(seen.t), counters, coverage, path.ahead);
      return {color, distance, coverage};
    }
    case Sighting::Kind::kCap:
      return {
          shadeCap(ray, *seen.capPlane, seen.t, seen.hit.face, seen.capMaterial, path.parallelView, counters),
          distance, 1.0f};
    case Sighting::Kind::kSurface:
      break;
  }
  return {shadeSurface(ray, seen.hit, distance, path), distance, 1.0f};
}

Vec3 Tracer::shadeSurface(const Ray& ray, const Hit& hit, float distance, const RayPath& path) const {
  const PrimaryAhead* ahead = path.ahead;
  // Edges are paint on the surface: fully covered pixels need no shading, partial ones blend.
  Vec3 edgeColor;
  const float edge = paint_.coverageAt(ray, hit, path.length, edgeColor);
  if (edge >= 1.0f) return edgeColor;
  SurfacePoint made;
  if (ahead == nullptr || !ahead->surfaceKnown) made = makeSurfacePoint(scene_, ray, hit);
  const SurfacePoint& surface = ahead != nullptr && ahead->surfaceKnown ? ahead->surface : made;
  // Isolines are paint too, under the edges.
  Vec3 isolineColor;
  const float isoline =
      isolineCoverage(scene_, ray, surface, paint_.pixelSizeAt(path.length + distance), isolineColor);
  auto withEdge = [&](Vec3 color) {
    if (isoline > 0.0f) color = color * (1.0f - isoline) + isolineColor * isoline;
    return edge > 0.0f ? color * (1.0f - edge) + edgeColor * edge : color;
  };
  // Closed shells and volumes face out of their material, so the side hit says whether the ray enters.
  const MediumCrossing media = queries_.crossingAt(hit.face, surface.normalSign > 0.0f);
  const Material& material = scene_.appearance.materials[media.shown];
  const EnergySplit& split = queries_.splitOf(media.shown);
  const Vec3 local = shadeLocal(ray, surface, material, path.parallelView, *path.counters, ahead);
  if (path.depth >= maxDepth_ || !split.recursive) return withEdge(local);

  const Vec3 direction = normalize(ray.direction);
  // Glass into water bends by n_glass / n_water; an open surface is a thin sheet.
  const InterfaceSplit weights = splitAtInterface(
      direction, surface.shadingNormal, surface.geometricNormal,
      scene_.geometry.faceBoundsSolid[hit.face] != 0, queries_.iorOf(media.from) / queries_.iorOf(media.to),
      material.fresnel, 1.0f / material.ior, split.reflect, split.transmit);
  RayPath branch = path;
  branch.length = path.length + distance;
  Vec3 color = local * split.local;
  // Reflected: the ray stays in the medium it came from (Beer-Lambert inside a solid).
  color += traceBranch(
      weights.reflect, queries_.absorptionOf(media.from), local,
      [&] {
        Vec3 reflected = reflect(direction, surface.shadingNormal);
        if (dot(reflected, surface.geometricNormal) <= 0.0f)
          reflected = reflect(direction, surface.geometricNormal);
        return Ray(offsetRayOrigin(surface.position, surface.geometricNormal), reflected);
      },
      branch);
  // Transmitted: into the medium beyond, absorbed along the segment inside it.
  color += traceBranch(
      Vec3{1, 1, 1} * weights.transmit, queries_.absorptionOf(media.to), local,
      [&] {
        return Ray(offsetRayOrigin(surface.position, -surface.geometricNormal), weights.transmittedDirection);
      },
      branch);
  return withEdge(color);
}

template <typename MakeRay>
Vec3 Tracer::traceBranch(const Vec3& weight, const Vec3& absorption, const Vec3& local, MakeRay&& makeRay,
                         const RayPath& path) const {
  const float branchWeight = path.weight * maxComponent(weight);
  if (branchWeight < kMinPathWeight) return local * weight;
  const TracedRay traced =
      trace(makeRay(), RayPath{path.depth + 1, branchWeight, path.length, false, path.counters, nullptr});
  Vec3 radiance = traced.color;
  if (maxComponent(absorption) > 0.0f)
    radiance *= std::isfinite(traced.distance) ? beerLambert(absorption, traced.distance) : Vec3{0, 0, 0};
  return radiance * weight;
}

}  // namespace lancer
