// Element edges on an outline, drawn whole. The tracer paints an edge where a ray hits one of its
// faces, so where only one face is seen (a part's silhouette against the background or against
// what lies behind it, an open surface's border) only the surface's half of the line was drawn.
// For one camera this finds those edges (faces on opposite sides of the eye, or a single face),
// bins them in screen cells, and gives the coverage of the half that falls beside the surface.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/render/camera.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

class OutlineEdges {
 public:
  // Empty (and free) when no mesh draws its edges.
  OutlineEdges(const Scene& scene, const Camera& camera, int imageWidth, int imageHeight);

  bool empty() const { return segments_.empty(); }

  // Coverage in [0, 1] of the outline edges near primary ray `ray` that `hitFace` (the face the ray
  // hit, or Hit's invalid face) does not draw itself and that lie in front of `hitDistance` (world
  // distance along the ray; infinity on a miss), with the covering edge's colour. `pixelSize`: the
  // world size of a pixel at distance d along the ray is footprint.at(d).
  float coverage(const Ray& ray, std::uint32_t hitFace, float hitDistance, const PixelFootprint& footprint,
                 Vec3& color) const;

  // Whether some outline edge passes near the pixel that `ray` goes through (a cheap first test).
  bool near(const Ray& ray) const;

 private:
  struct Segment {
    Vec3 a, b;
    std::uint32_t faces[2];  // the second is kNoFace on an open border
    std::uint16_t style;
  };
  static constexpr std::uint32_t kNoFace = 0xFFFFFFFFu;
  static constexpr int kMinCellPixels = 4;
  static constexpr int kMaxCellsAcross = 1024;

  int cellOf(const Ray& ray) const;  // -1 outside the image

  const Scene* scene_;
  const Camera* camera_;
  int cellPixels_ = kMinCellPixels;
  int cellsX_ = 0, cellsY_ = 0;
  std::vector<Segment> segments_;
  std::vector<std::uint32_t> cellStart_;  // cellsX_ * cellsY_ + 1 offsets into cellSegments_
  std::vector<std::uint32_t> cellSegments_;
};

}  // namespace lancer
