#include "lancer/render/edge_paint.hpp"

#include <algorithm>

#include "lancer/render/ray_offset.hpp"

namespace lancer {

EdgePaint::EdgePaint(const Scene& scene, const Camera& camera, int width, int height)
    : EdgePaint(scene, camera.pixelFootprint()) {
  outlines_.emplace(scene, camera, width, height);
  if (outlines_->empty()) outlines_.reset();
}

float EdgePaint::coverageAt(const Ray& ray, const Hit& hit, float pathLength, Vec3& color) const {
  if (!scene_.edges) return 0.0f;
  const EdgeOverlay& overlay = *scene_.edges;
  const std::uint16_t style = overlay.faceEdgeStyle[hit.face];
  if (style == 0) return 0.0f;
  color = overlay.styles[style].color;
  const MeshFace& face = scene_.geometry.faces[hit.face];
  Vec3 corners[4];
  for (int c = 0; c < face.cornerCount(); ++c) corners[c] = scene_.geometry.positions[face.vertex[c]];
  const float directionLength = length(ray.direction);
  const float pixelSize = footprint_.at(pathLength + hit.t * directionLength);
  return edgeCoverage(ray.origin, ray.direction * (1.0f / directionLength), corners, face.cornerCount(),
                      overlay.faceEdgeMask[hit.face], overlay.faceLineCorners[hit.face], pixelSize,
                      overlay.styles[style].widthPixels);
}

Sighting EdgePaint::sightingPastClearFaces(const SceneQueries& queries, Ray& ray, float& travelled,
                                           PaintLayer& paint, bool withCatcher) const {
  constexpr int kMaxClearFaces = 64;  // a ray crosses a few; coincident copies cannot loop forever
  for (int crossed = 0;; ++crossed) {
    const Sighting seen = queries.firstSighting(ray, nullptr, withCatcher);
    if (seen.kind != Sighting::Kind::kSurface || !queries.clearFace(seen.hit.face) ||
        crossed == kMaxClearFaces)
      return seen;
    Vec3 edgeColor;
    paint.add(std::min(coverageAt(ray, seen.hit, travelled, edgeColor), 1.0f), edgeColor);
    const float directionLength = length(ray.direction);
    travelled += seen.t * directionLength;
    const Vec3 point = ray.at(seen.t);
    const Vec3& normal = scene_.geometry.faceNormals[seen.hit.face];
    const Vec3 beyond = dot(normal, ray.direction) > 0.0f ? normal : -normal;
    ray =
        Ray(offsetRayOrigin(point, rayPointError(ray.origin, ray.direction, seen.t), beyond), ray.direction);
    if (paint.opaque()) return seen;
  }
}

void EdgePaint::paintOutlinesNear(const SceneQueries& queries, const Ray& ray, float hitDistance,
                                  TraceResult& result, TraceCounters& counters, const KnownHit* known) const {
  // The face the ray hit draws its own edges; the query is repeated only near outlines.
  ++counters.rays;
  const ClipInterval kept = clipRay(ray, scene_.clipping.planes);
  Hit hit;
  if (known != nullptr) {
    if (known->hit) hit = known->first;
  } else if (!kept.empty()) {
    queries.nearestHit(ray, kept.enter, kept.exit, hit);
  }
  Vec3 color;
  const float edge = outlines_->coverage(ray, hit.face, hitDistance, footprint_, color);
  if (edge <= 0.0f) return;
  result.color = result.color * (1.0f - edge) + color * edge;
  result.alpha = std::max(result.alpha, edge);
}

}  // namespace lancer
