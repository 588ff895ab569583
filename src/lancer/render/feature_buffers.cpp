#include "lancer/render/feature_buffers.hpp"

#include <algorithm>
#include <limits>

#include "lancer/render/edge_paint.hpp"
#include "lancer/render/field_shading.hpp"
#include "lancer/render/isoline_paint.hpp"
#include "lancer/render/scene_queries.hpp"
#include "lancer/render/surface_point.hpp"

namespace lancer {

Vec3 featureAlbedo(const Vec3& kd, const EnergySplit& split) {
  return kd * split.local + split.reflect + Vec3{1, 1, 1} * split.transmit;
}

void FeatureSum::store(FeatureBuffers& buffers, std::size_t k, int samples) const {
  const float weight = 1.0f / static_cast<float>(samples);
  buffers.albedo[k] = albedo * weight;
  buffers.normal[k] = normal * weight;
  buffers.depth[k] = hits > 0 ? depth / static_cast<float>(hits) : std::numeric_limits<float>::infinity();
}

SurfaceFeatures surfaceFeatures(const SceneQueries& queries, const EdgePaint& paint, const Ray& ray,
                                const Vec3& background, bool linearFieldColors) {
  const Scene& scene = queries.scene();
  SurfaceFeatures features;
  features.albedo = background;
  Ray past = ray;  // past the clear faces (the undeformed shape's): their edges are paint
  float travelled = 0.0f;
  PaintLayer front;
  const Sighting seen = paint.sightingPastClearFaces(queries, past, travelled, front);
  if (seen.kind == Sighting::Kind::kNothing || front.opaque()) {
    features.albedo = front.over(features.albedo);
    return features;
  }
  features.hit = true;
  features.depth = travelled + seen.t * length(past.direction);
  switch (seen.kind) {
    case Sighting::Kind::kNothing:
      break;
    case Sighting::Kind::kShadowCatcher:
      // The catcher shows the background darkened by shadows: the background is what it multiplies.
      features.normal = scene.shadowCatcher->normal;
      break;
    case Sighting::Kind::kCap:
      features.albedo =
          featureAlbedo(scene.appearance.materials[seen.capMaterial].kd, queries.splitOf(seen.capMaterial));
      features.normal = seen.capPlane->normal;  // the cap faces the removed side, where the ray came from
      break;
    case Sighting::Kind::kSurface: {
      const SurfacePoint surface = makeSurfacePoint(scene, past, seen.hit);
      const MediumCrossing media = queries.crossingAt(seen.hit.face, surface.normalSign > 0.0f);
      Vec3 kd = scene.appearance.materials[media.shown].kd;
      Vec3 fieldColor;
      if (fieldColorAt(scene, surface, linearFieldColors, fieldColor)) kd = fieldColor;
      Vec3 isolineColor;  // painted on the albedo, as the integrators paint them
      if (const float isoline =
              isolineCoverage(scene, past, surface, paint.pixelSizeAt(features.depth), isolineColor);
          isoline > 0.0f)
        kd = kd * (1.0f - isoline) + isolineColor * isoline;
      features.albedo = featureAlbedo(kd, queries.splitOf(media.shown));
      features.normal = surface.shadingNormal;
      // Drawn edges are paint: their colour is the albedo where they cover the pixel.
      Vec3 edgeColor;
      if (const float edge = std::min(paint.coverageAt(past, seen.hit, travelled, edgeColor), 1.0f);
          edge > 0.0f)
        features.albedo = features.albedo * (1.0f - edge) + edgeColor * edge;
      break;
    }
  }
  features.albedo = front.over(features.albedo);
  return features;
}

}  // namespace lancer
