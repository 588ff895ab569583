#include "lancer/render/feature_buffers.hpp"

#include <algorithm>

#include "lancer/render/edge_paint.hpp"
#include "lancer/render/field_shading.hpp"
#include "lancer/render/scene_queries.hpp"
#include "lancer/render/surface_point.hpp"

namespace lancer {
namespace {

// The share of the light leaving a point that its colour multiplies: kd for the local part; the
// reflected and transmitted parts carry what they meet, not kd (Open Image Denoise's convention).
Vec3 albedoOf(const Vec3& kd, const EnergySplit& split) {
  return kd * split.local + split.reflect + Vec3{1, 1, 1} * split.transmit;
}

}  // namespace

SurfaceFeatures surfaceFeatures(const SceneQueries& queries, const EdgePaint& paint, const Ray& ray,
                                const Vec3& background, bool linearFieldColors) {
  const Scene& scene = queries.scene();
  SurfaceFeatures features;
  features.albedo = background;
  const Sighting seen = queries.firstSighting(ray);
  if (seen.kind == Sighting::Kind::kNothing) return features;
  features.hit = true;
  features.depth = seen.t * length(ray.direction);
  switch (seen.kind) {
    case Sighting::Kind::kNothing:
      break;
    case Sighting::Kind::kShadowCatcher:
      // The catcher shows the background darkened by shadows: the background is what it multiplies.
      features.normal = scene.shadowCatcher->normal;
      break;
    case Sighting::Kind::kCap:
      features.albedo =
          albedoOf(scene.appearance.materials[seen.capMaterial].kd, queries.splitOf(seen.capMaterial));
      features.normal = seen.capPlane->normal;  // the cap faces the removed side, where the ray came from
      break;
    case Sighting::Kind::kSurface: {
      const SurfacePoint surface = makeSurfacePoint(scene, ray, seen.hit);
      const MediumCrossing media = queries.crossingAt(seen.hit.face, surface.normalSign > 0.0f);
      Vec3 kd = scene.appearance.materials[media.shown].kd;
      Vec3 fieldColor;
      if (fieldColorAt(scene, surface, linearFieldColors, fieldColor)) kd = fieldColor;
      features.albedo = albedoOf(kd, queries.splitOf(media.shown));
      features.normal = surface.shadingNormal;
      // Drawn edges are paint: their colour is the albedo where they cover the pixel.
      Vec3 edgeColor;
      if (const float edge = std::min(paint.coverageAt(ray, seen.hit, 0.0f, edgeColor), 1.0f); edge > 0.0f)
        features.albedo = features.albedo * (1.0f - edge) + edgeColor * edge;
      break;
    }
  }
  return features;
}

}  // namespace lancer
