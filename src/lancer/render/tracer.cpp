#include "lancer/render/tracer.hpp"

#include <cmath>
#include <limits>

#include "lancer/render/lighting.hpp"
#include "lancer/render/ray_offset.hpp"

namespace lancer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Paths whose weight in the pixel falls below this cannot change an 8-bit value by more than half a step.
constexpr float kMinPathWeight = 1.0f / 512.0f;
// Transparent surfaces a shadow ray may cross before the light counts as blocked.
constexpr int kMaxShadowCrossings = 16;

Vec3 reflect(const Vec3& direction, const Vec3& normal) { return direction - normal * (2.0f * dot(direction, normal)); }

// Snell's law; `normal` faces the incoming side, eta = n_incoming / n_transmitted. False on total
// internal reflection.
bool refract(const Vec3& direction, const Vec3& normal, float eta, Vec3& transmitted) {
  const float cosIncident = -dot(direction, normal);
  const float k = 1.0f - eta * eta * (1.0f - cosIncident * cosIncident);
  if (k < 0.0f) return false;
  transmitted = normalize(direction * eta + normal * (eta * cosIncident - std::sqrt(k)));
  return true;
}

// Exact unpolarised dielectric Fresnel reflectance (Born & Wolf), cosIncident in [0, 1].
float dielectricFresnel(float cosIncident, float eta) {
  const float sin2Transmitted = eta * eta * (1.0f - cosIncident * cosIncident);
  if (sin2Transmitted >= 1.0f) return 1.0f;
  const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
  const float rs = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
  const float rp = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
  return 0.5f * (rs * rs + rp * rp);
}

// Tint of the light that passes through a transparent surface: its diffuse colour at full
// brightness (white when it has none), so a blue glass casts a blue shadow.
Vec3 transmissionTint(const Material& material) {
  const float brightest = maxComponent(material.kd);
  return brightest > 0.0f ? material.kd * (1.0f / brightest) : Vec3{1, 1, 1};
}

Vec3 expNegative(const Vec3& v) { return {std::exp(-v.x), std::exp(-v.y), std::exp(-v.z)}; }

}  // namespace

Tracer::Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings)
    : scene_(scene), accelerator_(accelerator), background_(settings.background), maxDepth_(settings.maxDepth) {
  for (const Material& material : scene.materials) anyTransparent_ = anyTransparent_ || material.transparency > 0;
}

TraceResult Tracer::tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters) const {
  bool hitSomething = false;
  float hitDistance = 0;
  TraceResult result;
  result.color = trace(ray, 0, 1.0f, parallelView, counters, hitSomething, hitDistance);
  result.alpha = hitSomething ? 1.0f : 0.0f;
  return result;
}

Vec3 Tracer::lightTransmission(const Vec3& from, const Vec3& lightPosition, TraceCounters& counters) const {
  if (!anyTransparent_) {
    ++counters.rays;
    return accelerator_.occluded(Ray(from, lightPosition - from), 0.0f, 1.0f) ? Vec3{0, 0, 0} : Vec3{1, 1, 1};
  }
  Vec3 transmission{1, 1, 1};
  Vec3 origin = from;
  for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
    ++counters.rays;
    const Ray ray(origin, lightPosition - origin);
    Hit hit;
    if (!accelerator_.intersect(ray, 0.0f, 1.0f, hit)) return transmission;
    const Material& material = scene_.materials[scene_.faceMaterial[hit.face]];
    if (material.transparency <= 0.0f) return {0, 0, 0};
    transmission *= transmissionTint(material) * material.transparency;
    if (maxComponent(transmission) < kMinPathWeight) return {0, 0, 0};
    const Vec3 normal = scene_.faceNormals[hit.face];
    origin = offsetRayOrigin(ray.at(hit.t), dot(normal, ray.direction) > 0 ? normal : -normal);
  }
  return {0, 0, 0};
}

Vec3 Tracer::shadeLocal(const Ray& ray, const SurfacePoint& surface, const Material& material, bool parallelView,
                        TraceCounters& counters) const {
  Vec3 color = scene_.ambient * material.ka;
  const Vec3 toViewer = normalize(-ray.direction);
  const MeshFace& face = scene_.faces[surface.face];
  const bool gouraud = scene_.faceShading[surface.face] == ShadingMode::Gouraud;
  for (const SceneLight& light : scene_.lights) {
    const Vec3 toLight = light.position - surface.position;
    const float distance = length(toLight);
    if (!(distance > 0.0f)) continue;
    const Vec3 lightDirection = toLight * (1.0f / distance);
    Vec3 contribution{0, 0, 0};
    if (gouraud) {
      // The light's response at each corner, with the corner's own normal and view direction,
      // interpolated across the face; only the shadow test is per pixel.
      const auto& corners = scene_.cornerNormals.faceCorner[surface.face];
      for (int c = 0; c < face.cornerCount(); ++c) {
        const Vec3& corner = scene_.positions[face.vertex[c]];
        const Vec3 cornerNormal = scene_.cornerNormals.normals[corners[c]] * surface.normalSign;
        const Vec3 cornerToViewer = parallelView ? toViewer : normalize(ray.origin - corner);
        const Vec3 cornerToLight = light.position - corner;
        const float cornerDistance = length(cornerToLight);
        contribution += directLighting(material, light, cornerNormal, cornerToViewer,
                                       cornerToLight * (1.0f / cornerDistance), cornerDistance) *
                        surface.cornerWeight[c];
      }
    } else {
      contribution = directLighting(material, light, surface.shadingNormal, toViewer, lightDirection, distance);
    }
    if (maxComponent(contribution) <= 0.0f) continue;
    // A light behind the geometric surface is blocked by the surface itself.
    if (dot(surface.geometricNormal, lightDirection) <= 0.0f) continue;
    const Vec3 shadowOrigin = offsetRayOrigin(surface.position, surface.geometricNormal);
    color += contribution * lightTransmission(shadowOrigin, light.position, counters);
  }
  return color;
}

Vec3 Tracer::trace(const Ray& ray, int depth, float pathWeight, bool parallelView, TraceCounters& counters,
                   bool& hitSomething, float& hitDistance) const {
  ++counters.rays;
  Hit hit;
  if (!accelerator_.intersect(ray, 0.0f, kInfinity, hit)) {
    hitDistance = kInfinity;
    return background_;
  }
  hitSomething = true;
  hitDistance = hit.t;
  const SurfacePoint surface = makeSurfacePoint(scene_, ray, hit);
  const Material& material = scene_.materials[scene_.faceMaterial[hit.face]];
  const Vec3 local = shadeLocal(ray, surface, material, parallelView, counters);
  if (depth >= maxDepth_ || (maxComponent(material.reflectivity) <= 0.0f && material.transparency <= 0.0f))
    return local;

  // Energy split: of the light leaving this point, a share `reflectivity` is mirror reflection,
  // `transparency` is transmission (split further by Fresnel when asked, and sent back as
  // reflection on total internal reflection) and the rest, 1 - reflectivity - transparency, is the
  // local model. The weights are non-negative and sum to at most 1, so recursion adds no energy.
  const Vec3 direction = normalize(ray.direction);
  Vec3 normal = surface.shadingNormal;
  Vec3 reflectWeight = material.reflectivity;
  float transmitWeight = material.transparency;
  const Vec3 localWeight = max(Vec3{1, 1, 1} - reflectWeight - Vec3{1, 1, 1} * transmitWeight, Vec3{0, 0, 0});

  Vec3 transmittedDirection;
  bool transmits = false;
  if (transmitWeight > 0.0f) {
    const bool entering = surface.normalSign > 0.0f;  // hit the outside of an outward-oriented shell
    const float eta = entering ? 1.0f / material.ior : material.ior;
    if (refract(direction, normal, eta, transmittedDirection) ||
        refract(direction, surface.geometricNormal, eta, transmittedDirection)) {
      transmits = true;
      if (material.fresnel) {
        const float fresnel = dielectricFresnel(std::clamp(-dot(direction, normal), 0.0f, 1.0f), eta);
        reflectWeight += Vec3{1, 1, 1} * (transmitWeight * fresnel);
        transmitWeight *= 1.0f - fresnel;
      }
    } else {  // total internal reflection: everything transmitted is reflected instead
      reflectWeight += Vec3{1, 1, 1} * transmitWeight;
      transmitWeight = 0.0f;
    }
  }

  Vec3 color = local * localWeight;
  if (pathWeight * maxComponent(reflectWeight) >= kMinPathWeight) {
    Vec3 reflected = reflect(direction, normal);
    if (dot(reflected, surface.geometricNormal) <= 0.0f) reflected = reflect(direction, surface.geometricNormal);
    float distance = 0;
    const Ray reflectedRay(offsetRayOrigin(surface.position, surface.geometricNormal), reflected);
    color += trace(reflectedRay, depth + 1, pathWeight * maxComponent(reflectWeight), false, counters,
                   hitSomething, distance) *
             reflectWeight;
  }
  if (transmits && pathWeight * transmitWeight >= kMinPathWeight) {
    float distance = 0;
    const Ray transmittedRay(offsetRayOrigin(surface.position, -surface.geometricNormal), transmittedDirection);
    Vec3 transmitted = trace(transmittedRay, depth + 1, pathWeight * transmitWeight, false, counters,
                             hitSomething, distance);
    // Beer-Lambert absorption along the segment inside the medium (entering an outward shell).
    if (surface.normalSign > 0.0f && maxComponent(material.absorption) > 0.0f)
      transmitted *= std::isfinite(distance) ? expNegative(material.absorption * distance) : Vec3{0, 0, 0};
    color += transmitted * transmitWeight;
  }
  return color;
}

}  // namespace lancer
