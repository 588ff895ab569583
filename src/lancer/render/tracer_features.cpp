// Tracer::surfaceFeatures: the first surface a primary ray sees, as the shading would see it (cut
// views, caps, the shadow catcher, field colours, drawn edges), without any lighting.
#include <algorithm>

#include "lancer/render/field_shading.hpp"
#include "lancer/render/tracer.hpp"

namespace lancer {
namespace {

// The share of the light leaving a point that its colour multiplies: kd for the local part; the
// reflected and transmitted parts carry what they meet, not kd (OIDN's convention for albedo).
Vec3 albedoOf(const Vec3& kd, const EnergySplit& split) {
  return kd * split.local + split.reflect + Vec3{1, 1, 1} * split.transmit;
}

}  // namespace

SurfaceFeatures Tracer::surfaceFeatures(const Ray& ray) const {
  SurfaceFeatures features;
  features.albedo = background_;
  const Sighting seen = firstSighting(ray);
  if (seen.kind == Sighting::Kind::kNothing) return features;
  features.hit = true;
  features.depth = seen.t * length(ray.direction);
  switch (seen.kind) {
    case Sighting::Kind::kNothing:
      break;
    case Sighting::Kind::kShadowCatcher:
      // The catcher shows the background darkened by shadows: the background is what it multiplies.
      features.normal = scene_.shadowCatcher->normal;
      break;
    case Sighting::Kind::kCap: {
      const Material& material = scene_.appearance.materials[seen.capMaterial];
      features.albedo = albedoOf(material.kd, splits_[seen.capMaterial]);
      features.normal = seen.capPlane->normal;
      break;
    }
    case Sighting::Kind::kSurface: {
      const SurfacePoint surface = makeSurfacePoint(scene_, ray, seen.hit);
      const MediumCrossing media = crossingAt(seen.hit.face, surface.normalSign > 0.0f);
      const Material& material = scene_.appearance.materials[media.shown];
      Vec3 kd = material.kd;
      Vec3 fieldColor;
      if (fieldColorAt(scene_, surface, linearFieldColors_, fieldColor)) kd = fieldColor;
      features.albedo = albedoOf(kd, splits_[media.shown]);
      features.normal = surface.shadingNormal;
      // Drawn edges are paint: their colour is the albedo where they cover the pixel.
      if (const float edge = edgeCoverageAt(ray, seen.hit, 0.0f); edge > 0.0f) {
        const Vec3 edgeColor = scene_.edges->styles[scene_.edges->faceEdgeStyle[seen.hit.face]].color;
        features.albedo = features.albedo * (1.0f - std::min(edge, 1.0f)) + edgeColor * std::min(edge, 1.0f);
      }
      break;
    }
  }
  return features;
}

}  // namespace lancer
