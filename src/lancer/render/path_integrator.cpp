#include "lancer/render/path_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/render/bsdf.hpp"
#include "lancer/render/field_shading.hpp"
#include "lancer/render/isoline_paint.hpp"
#include "lancer/render/light_sampling.hpp"
#include "lancer/render/optics.hpp"
#include "lancer/render/ray_offset.hpp"
#include "lancer/render/shading.hpp"

namespace lancer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr int kRouletteFrom = 3;  // bounces before Russian roulette may end a path

}  // namespace

PathIntegrator::PathIntegrator(const Scene& scene, const Accelerator& accelerator,
                               const RenderSettings& settings, const Camera& camera)
    : scene_(scene),
      queries_(scene, accelerator),
      paint_(scene, camera, settings.width, settings.height),
      emissive_(scene),
      background_(settings.background),
      maxBounces_(settings.maxBounces),
      sceneSize_(scene.geometry.bounds.empty() ? 1.0f : length(scene.geometry.bounds.extent())),
      linearFieldColors_(settings.srgb) {
  if (scene.environment) environment_ = EnvironmentLight(*scene.environment);
}

Vec3 PathIntegrator::missColor(const Vec3& direction) const {
  return scene_.environment && scene_.environment->visible ? environment_.radiance(direction) : background_;
}

Vec3 PathIntegrator::escaped(const Vec3& origin, const Vec3& direction, float bsdfPdf) const {
  Vec3 radiance = lightsAlongRay(scene_.appearance.lights, origin, direction, kInfinity, bsdfPdf);
  if (environment_.black()) return radiance;
  const float weight =
      environment_.sampled() && bsdfPdf > 0.0f ? powerHeuristic(bsdfPdf, environment_.pdf(direction)) : 1.0f;
  return radiance + environment_.radiance(direction) * weight;
}

Vec3 PathIntegrator::directLight(const SurfacePoint& surface, const Vec3& shadowOrigin, const LocalBsdf& bsdf,
                                 float lobeChance, SampleStream& samples, TraceCounters& counters) const {
  Vec3 sum{0, 0, 0};
  auto addLightSample = [&](const LightSample& sample) {
    if (dot(surface.geometricNormal, sample.direction) <= 0.0f) return;
    const Vec3 f = bsdf.eval(sample.direction);
    if (maxComponent(f) <= 0.0f) return;
    const Vec3 through = queries_.lightTransmission(shadowOrigin, sample.target, counters);
    if (maxComponent(through) <= 0.0f) return;
    const float weight =
        sample.pdf > 0.0f ? powerHeuristic(sample.pdf, lobeChance * bsdf.pdf(sample.direction)) : 1.0f;
    sum += f * sample.weight * through * (dot(surface.shadingNormal, sample.direction) * weight);
  };
  // Each light gets its pair of dimensions whether or not it lights the point, so the dimensions
  // of a path do not depend on which lights are behind it.
  for (const SceneLight& light : scene_.appearance.lights) {
    float u, v;
    samples.next2D(u, v);
    LightSample sample;
    if (sampleLight(light, surface.position, u, v, sceneSize_, sample)) addLightSample(sample);
  }
  if (!emissive_.empty()) {
    float u, v;
    samples.next2D(u, v);
    LightSample sample;
    if (emissive_.sample(surface.position, u, v, sample)) addLightSample(sample);
  }
  if (environment_.sampled()) {
    float u, v, pdf;
    samples.next2D(u, v);
    Vec3 radiance;
    const Vec3 direction = environment_.sample(u, v, pdf, radiance);
    if (pdf > 0.0f && dot(surface.geometricNormal, direction) > 0.0f) {
      const Vec3 f = bsdf.eval(direction);
      if (maxComponent(f * radiance) > 0.0f) {
        const Vec3 through = queries_.lightTransmission(
            shadowOrigin, shadowOrigin + direction * (4.0f * sceneSize_ + 1.0f), counters);
        const float weight = powerHeuristic(pdf, lobeChance * bsdf.pdf(direction));
        sum += f * radiance * through * (dot(surface.shadingNormal, direction) * weight / pdf);
      }
    }
  }
  return sum;
}

Vec3 PathIntegrator::shadeShadowCatcher(const Vec3& point, const Vec3& direction, SampleStream& samples,
                                        TraceCounters& counters, float& coverage) const {
  // The irradiance the floor gets with the meshes in the way over what it would get without them.
  const Vec3& normal = scene_.shadowCatcher->normal;
  const Vec3 from = offsetRayOrigin(point, normal);
  Vec3 lit{0, 0, 0}, shadowed{0, 0, 0};
  auto catchSample = [&](const LightSample& sample) {
    const float cosTheta = dot(normal, sample.direction);
    if (cosTheta <= 0.0f) return;
    const Vec3 irradiance = sample.weight * cosTheta;
    lit += irradiance;
    shadowed += irradiance * queries_.lightTransmission(from, sample.target, counters);
  };
  for (const SceneLight& light : scene_.appearance.lights) {
    float u, v;
    samples.next2D(u, v);
    LightSample sample;
    if (sampleLight(light, point, u, v, sceneSize_, sample)) catchSample(sample);
  }
  if (!emissive_.empty()) {
    float u, v;
    samples.next2D(u, v);
    LightSample sample;
    if (emissive_.sample(point, u, v, sample)) catchSample(sample);
  }
  if (!environment_.black()) {
    float u, v;
    samples.next2D(u, v);
    const Vec3 toSky = sampleCosine(normal, u, v);  // irradiance = pi L for a cosine-weighted sample
    const Vec3 irradiance = environment_.radiance(toSky) * kPi;
    lit += irradiance;
    shadowed +=
        irradiance * queries_.lightTransmission(from, from + toSky * (4.0f * sceneSize_ + 1.0f), counters);
  }
  auto ratio = [](float s, float l) { return l > 0.0f ? std::clamp(s / l, 0.0f, 1.0f) : 1.0f; };
  const Vec3 kept{ratio(shadowed.x, lit.x), ratio(shadowed.y, lit.y), ratio(shadowed.z, lit.z)};
  coverage = 1.0f - (kept.x + kept.y + kept.z) / 3.0f;
  return missColor(direction) * kept;
}

TraceResult PathIntegrator::li(const Ray& cameraRay, SampleStream& samples, TraceCounters& counters,
                               SurfaceFeatures* first) const {
  TraceResult result;
  Vec3 radiance{0, 0, 0}, throughput{1, 1, 1};
  float firstDistance = kInfinity;
  PaintLayer paint;          // the edges the camera ray meets, over what it sees
  float travelled = 0.0f;    // by the camera ray past clear faces
  float previousPdf = 0.0f;  // of the direction the current ray was sampled with; 0: a delta or the camera
  Ray ray = cameraRay;
  // The camera's own sighting: what lies in front, past clear faces (their edges painted), and
  // the paint and coverage that leaves over it.
  auto firstPaint = [&](TraceResult seenFirst, float distance) {
    seenFirst.color = paint.over(seenFirst.color);
    if (seenFirst.alpha < 1.0f) seenFirst.alpha = paint.coverage + seenFirst.alpha * (1.0f - paint.coverage);
    paint_.paintOutlines(queries_, cameraRay, distance, seenFirst, counters, nullptr);
    return seenFirst;
  };
  // The features of what the camera ray sees first, under the paint in front of it (as
  // surfaceFeatures sees them, feature_buffers.hpp).
  auto noteFirst = [&](const Vec3& albedo, const Vec3& normal, float depth, bool hit) {
    if (first == nullptr) return;
    first->albedo = paint.over(albedo);
    first->normal = normal;
    first->depth = depth;
    first->hit = hit;
  };
  for (int bounce = 0;; ++bounce) {
    ++counters.rays;
    const Sighting seen = bounce == 0 ? paint_.sightingPastClearFaces(queries_, ray, travelled, paint)
                                      : queries_.firstSighting(ray, nullptr, false);
    const float directionLength = length(ray.direction);
    const Vec3 direction = ray.direction * (1.0f / directionLength);
    if (bounce == 0 && paint.opaque()) {
      noteFirst(background_, Vec3{0, 0, 0}, 0.0f, false);
      return firstPaint(TraceResult{}, travelled);
    }
    if (seen.kind == Sighting::Kind::kNothing) {
      if (bounce == 0) {
        noteFirst(background_, Vec3{0, 0, 0}, 0.0f, false);
        return firstPaint(TraceResult{missColor(direction), 0.0f}, kInfinity);
      }
      radiance += throughput * escaped(ray.origin, direction, previousPdf);
      break;
    }
    const float distance = seen.t * directionLength;
    if (seen.kind == Sighting::Kind::kShadowCatcher) {
      noteFirst(background_, scene_.shadowCatcher->normal, travelled + distance, true);
      TraceResult caught;
      caught.color = shadeShadowCatcher(ray.at(seen.t), direction, samples, counters, caught.alpha);
      return firstPaint(caught, travelled + distance);
    }
    if (bounce == 0) {
      result.alpha = 1.0f;
      firstDistance = travelled + distance;
    } else {
      radiance +=
          throughput * lightsAlongRay(scene_.appearance.lights, ray.origin, direction, distance, previousPdf);
    }

    // The surface: a face (with the media it separates) or a cap (opaque, in the cut solid's material).
    const bool isCap = seen.kind == Sighting::Kind::kCap;
    const SurfacePoint surface = isCap ? makeCapPoint(scene_, ray, *seen.capPlane, seen.t, seen.hit.face)
                                       : makeSurfacePoint(scene_, ray, seen.hit);
    MediumCrossing media{SceneAppearance::kNoMaterial, SceneAppearance::kNoMaterial, seen.capMaterial};
    if (!isCap) {
      media = queries_.crossingAt(seen.hit.face, surface.normalSign > 0.0f);
      if (bounce == 0) {
        Vec3 edgeColor;
        paint.add(std::min(paint_.coverageAt(ray, seen.hit, travelled, edgeColor), 1.0f), edgeColor);
        if (paint.opaque()) {
          noteFirst(Vec3{0, 0, 0}, surface.shadingNormal, firstDistance, true);
          break;
        }
      }
      const Vec3 absorption = queries_.absorptionOf(media.from);
      if (maxComponent(absorption) > 0.0f) throughput *= beerLambert(absorption, distance);
    }
    const Material& material = scene_.appearance.materials[media.shown];
    if (maxComponent(material.emission) > 0.0f) {
      // Found by the material's sample: weighted against next-event estimation's choice of the point.
      const float weight =
          previousPdf > 0.0f && !isCap
              ? powerHeuristic(previousPdf, emissive_.pdf(seen.hit.face, distance,
                                                          std::abs(dot(surface.geometricNormal, direction))))
              : 1.0f;
      radiance += throughput * material.emission * weight;
    }
    // The surface's albedo: the field's colour or the material's, with the isolines painted on it
    // where the camera sees it first (as the edges are).
    Vec3 albedo;
    if (!fieldColorAt(scene_, surface, linearFieldColors_, albedo)) albedo = material.kd;
    if (bounce == 0) {
      Vec3 isolineColor;
      const float isoline =
          isolineCoverage(scene_, ray, surface, paint_.pixelSizeAt(travelled + distance), isolineColor);
      if (isoline > 0.0f) albedo = albedo * (1.0f - isoline) + isolineColor * isoline;
      noteFirst(featureAlbedo(albedo, queries_.splitOf(media.shown)),
                isCap ? seen.capPlane->normal : surface.shadingNormal, firstDistance, true);
    }
    if (unlitFace(scene_, surface.face)) {  // the colour as it is: no light, no bounce
      radiance += throughput * albedo;
      break;
    }
    if (bounce >= maxBounces_) break;

    // The lobes: mirror and dielectric shares first (optics.hpp), the local lobe the rest.
    const EnergySplit& split = queries_.splitOf(media.shown);
    InterfaceSplit delta{{0, 0, 0}, 0.0f, direction};
    Vec3 localWeight{1, 1, 1};
    if (!isCap && split.recursive) {
      delta = splitAtInterface(direction, surface.shadingNormal, surface.geometricNormal,
                               scene_.geometry.faceBoundsSolid[seen.hit.face] != 0,
                               queries_.iorOf(media.from) / queries_.iorOf(media.to), material.fresnel,
                               1.0f / material.ior, split.reflect, split.transmit);
      localWeight = split.local;
    }
    const LocalBsdf bsdf(albedo, material.ks, material.shininess, surface.shadingNormal, -direction);
    const float chanceLocal = bsdf.black() ? 0.0f : maxComponent(localWeight);
    const float chanceReflect = maxComponent(delta.reflect), chanceTransmit = delta.transmit;
    const float chances = chanceLocal + chanceReflect + chanceTransmit;
    if (!(chances > 0.0f)) break;

    const Vec3 shadowOrigin =
        offsetRayOrigin(surface.position, surface.positionError, surface.geometricNormal);
    if (chanceLocal > 0.0f)
      radiance += throughput * localWeight *
                  directLight(surface, shadowOrigin, bsdf, chanceLocal / chances, samples, counters);

    float lobe, u, v;
    samples.next2D(lobe, u);
    v = samples.next1D();
    lobe *= chances;
    if (lobe < chanceLocal) {
      const float choose = lobe / chanceLocal;
      Vec3 wi = bsdf.sample(choose, u, v);
      const float pdf = bsdf.pdf(wi) * (chanceLocal / chances);
      if (!(pdf > 0.0f)) break;
      throughput *= localWeight * bsdf.eval(wi) * (dot(wi, surface.shadingNormal) / pdf);
      previousPdf = pdf;
      // A direction about the interpolated normal may point under the flat face: mirrored back out
      // through the face's plane, with its weight, rather than lost (a tessellated sphere in the white
      // furnace would otherwise come out darker at every sample that does).
      const float below = dot(wi, surface.geometricNormal);
      if (below <= 0.0f) wi = normalize(wi - surface.geometricNormal * (2.0f * below));
      ray = Ray(shadowOrigin, wi);
    } else if (lobe < chanceLocal + chanceReflect) {
      Vec3 reflected = reflect(direction, surface.shadingNormal);
      if (dot(reflected, surface.geometricNormal) <= 0.0f)
        reflected = reflect(direction, surface.geometricNormal);
      throughput *= delta.reflect * (chances / chanceReflect);
      previousPdf = 0.0f;
      ray = Ray(offsetRayOrigin(surface.position, surface.geometricNormal), reflected);
    } else {
      // Through glass: the shadow rays of next-event estimation already pass transparent faces
      // (tinted, unbent), so the path keeps the pdf of the direction it was sampled with, and a
      // light seen through a thin sheet is weighted as if seen directly.
      throughput *= Vec3{1, 1, 1} * (delta.transmit * chances / chanceTransmit);
      ray = Ray(offsetRayOrigin(surface.position, -surface.geometricNormal), delta.transmittedDirection);
    }
    if (bounce + 1 >= kRouletteFrom) {
      const float survive = std::min(0.95f, maxComponent(throughput));
      if (samples.next1D() >= survive) break;
      throughput = throughput * (1.0f / survive);
    }
  }
  result.color = paint.over(radiance);
  paint_.paintOutlines(queries_, cameraRay, firstDistance, result, counters, nullptr);
  return result;
}

}  // namespace lancer
