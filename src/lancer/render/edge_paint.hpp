// Element edges painted on the surfaces (edge_overlay.hpp) and the outline edges drawn whole
// (outline_edges.hpp), for every integrator: how much of a pixel the edges at a hit cover.
#pragma once

#include <optional>

#include "lancer/render/camera.hpp"
#include "lancer/render/edge_overlay.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/render/outline_edges.hpp"
#include "lancer/render/scene_queries.hpp"

namespace lancer {

// Paint in front of what a camera ray sees (edges on the faces it hit or passed): the share of the
// pixel it covers and its colour times that share, laid over the light from behind by `over`.
struct PaintLayer {
  Vec3 color{0, 0, 0};
  float coverage = 0;

  void add(float share, const Vec3& paint) {
    const float seen = share * (1.0f - coverage);
    color += paint * seen;
    coverage += seen;
  }
  bool opaque() const { return coverage >= 1.0f; }
  Vec3 over(const Vec3& behind) const { return color + behind * (1.0f - coverage); }
};

class EdgePaint {
 public:
  // `footprint`: the world size of a pixel along primary rays, for edges drawn in pixel widths.
  EdgePaint(const Scene& scene, PixelFootprint footprint) : scene_(scene), footprint_(footprint) {}
  // For primary rays of `camera` (which must outlive this): edges on outlines are drawn whole.
  EdgePaint(const Scene& scene, const Camera& camera, int width, int height);

  // Coverage of the hit face's drawn edges at the hit (0 when its mesh draws none), with their colour.
  // `pathLength`: how far the ray's origin is from the eye along the path.
  float coverageAt(const Ray& ray, const Hit& hit, float pathLength, Vec3& color) const;
  // What `ray` sees first past the faces that let it through untouched (SceneQueries::clearFace: the
  // undeformed shape's surface under undeformed = "edges", which is lines, never a surface): the
  // edges drawn on those go into `paint`, and `ray` starts past the last of them, `travelled` (world
  // units) from where it started. Stops early when the paint covers the pixel.
  Sighting sightingPastClearFaces(const SceneQueries& queries, Ray& ray, float& travelled, PaintLayer& paint,
                                  bool withCatcher = true) const;
  // The world size of a pixel at `distance` from the eye along a path, for other paint (isolines).
  float pixelSizeAt(float distance) const { return footprint_.at(distance); }
  // Paints the outer half of outline edges over what primary ray `ray` saw at `hitDistance`;
  // `known`: the ray's first query, already answered.
  void paintOutlines(const SceneQueries& queries, const Ray& ray, float hitDistance, TraceResult& result,
                     TraceCounters& counters, const KnownHit* known) const {
    if (outlines_ && outlines_->near(ray))
      paintOutlinesNear(queries, ray, hitDistance, result, counters, known);
  }

 private:
  void paintOutlinesNear(const SceneQueries& queries, const Ray& ray, float hitDistance, TraceResult& result,
                         TraceCounters& counters, const KnownHit* known) const;

  const Scene& scene_;
  PixelFootprint footprint_;
  std::optional<OutlineEdges> outlines_;  // with a camera, when some mesh draws its edges
};

}  // namespace lancer
