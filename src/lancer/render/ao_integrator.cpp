#include "lancer/render/ao_integrator.hpp"

#include <algorithm>
#include <limits>

#include "lancer/render/field_shading.hpp"
#include "lancer/render/isoline_paint.hpp"
#include "lancer/render/light_sampling.hpp"
#include "lancer/render/ray_offset.hpp"
#include "lancer/render/shading.hpp"
#include "lancer/render/surface_point.hpp"

namespace lancer {

AoIntegrator::AoIntegrator(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
                           const Camera& camera)
    : scene_(scene),
      queries_(scene, accelerator),
      paint_(scene, camera, settings.width, settings.height),
      background_(settings.background),
      distance_(settings.aoDistance > 0.0f      ? settings.aoDistance
                : scene.geometry.bounds.empty() ? 1.0f
                                                : 0.1f * length(scene.geometry.bounds.extent())),
      linearFieldColors_(settings.srgb) {
  if (scene.environment) environment_ = EnvironmentLight(*scene.environment);
}

float AoIntegrator::openness(const Vec3& from, const Vec3& direction, TraceCounters& counters) const {
  return maxComponent(queries_.lightTransmission(from, from + direction * distance_, counters)) > 0.0f ? 1.0f
                                                                                                       : 0.0f;
}

TraceResult AoIntegrator::li(const Ray& cameraRay, SampleStream& samples, TraceCounters& counters) const {
  TraceResult result;
  ++counters.rays;
  Ray ray = cameraRay;
  PaintLayer paint;  // edges on the faces the ray passes (the undeformed shape's) and on the one it hits
  float travelled = 0.0f;
  const Sighting seen = paint_.sightingPastClearFaces(queries_, ray, travelled, paint);
  const float distance = travelled + seen.t * length(ray.direction);
  // The paint in front over what the ray sees, then the outlines over both.
  auto finish = [&](float hitDistance) {
    result.color = paint.over(result.color);
    if (result.alpha < 1.0f) result.alpha = paint.coverage + result.alpha * (1.0f - paint.coverage);
    paint_.paintOutlines(queries_, cameraRay, hitDistance, result, counters, nullptr);
    return result;
  };
  float u, v;
  samples.next2D(u, v);
  if (paint.opaque()) return finish(travelled);
  switch (seen.kind) {
    case Sighting::Kind::kNothing:
      result.color = background_;
      return finish(std::numeric_limits<float>::infinity());
    case Sighting::Kind::kShadowCatcher: {
      const Vec3& normal = scene_.shadowCatcher->normal;
      const Vec3 from = offsetRayOrigin(ray.at(seen.t), normal);
      const float open = openness(from, sampleCosine(normal, u, v), counters);
      result.color = background_ * open;
      result.alpha = 1.0f - open;
      return finish(distance);
    }
    case Sighting::Kind::kCap:
    case Sighting::Kind::kSurface:
      break;
  }
  SurfacePoint surface;
  std::uint32_t material;
  if (seen.kind == Sighting::Kind::kCap) {
    surface = SurfacePoint{};
    surface.face = seen.hit.face;
    surface.position = ray.at(seen.t);
    surface.positionError = rayPointError(ray.origin, ray.direction, seen.t);
    surface.geometricNormal = surface.shadingNormal = seen.capPlane->normal;
    surface.normalSign = 1.0f;
    surface.isCap = true;
    const int corners = scene_.geometry.faces[seen.hit.face].cornerCount();
    for (int c = 0; c < corners; ++c) surface.cornerWeight[c] = 1.0f / static_cast<float>(corners);
    material = seen.capMaterial;
  } else {
    surface = makeSurfacePoint(scene_, ray, seen.hit);
    material = queries_.crossingAt(seen.hit.face, surface.normalSign > 0.0f).shown;
    Vec3 edgeColor;
    paint.add(std::min(paint_.coverageAt(ray, seen.hit, travelled, edgeColor), 1.0f), edgeColor);
  }
  Vec3 kd;
  if (!fieldColorAt(scene_, surface, linearFieldColors_, kd)) kd = scene_.appearance.materials[material].kd;
  Vec3 isolineColor;  // painted on the albedo, as the field's colour is
  const float isoline = isolineCoverage(scene_, ray, surface, paint_.pixelSizeAt(distance), isolineColor);
  if (isoline > 0.0f) kd = kd * (1.0f - isoline) + isolineColor * isoline;
  const Vec3 direction = sampleCosine(surface.shadingNormal, u, v);
  Vec3 color{0, 0, 0};
  if (unlitFace(scene_, surface.face)) {
    color = kd;
  } else if (dot(direction, surface.geometricNormal) > 0.0f) {
    const Vec3 from = offsetRayOrigin(surface.position, surface.positionError, surface.geometricNormal);
    const Vec3 light = scene_.environment ? environment_.radiance(direction) : Vec3{1, 1, 1};
    color = kd * light * openness(from, direction, counters);
  }
  result.color = color;
  result.alpha = 1.0f;
  return finish(distance);
}

}  // namespace lancer
