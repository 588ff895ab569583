// The simplest accelerator: test every triangle. Slow (linear in faces) but obviously right,
// it is the reference that the kd-tree is checked against.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/face_clip_sets.hpp"

namespace lancer {

class NaiveAccel {
 public:
  NaiveAccel(std::span<const Vec3> positions, std::span<const MeshFace> faces)
      : triangles_(packTriangles(positions, faces)) {}

  // Closest hit with t in (tMin, tMax); returns false (hit untouched) when there is none.
  bool intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const {
    return closest(
        ray, tMin, tMax, [](std::uint32_t, float) { return true; }, hit);
  }
  // The same among the hits per-mesh clip planes keep: a removed face is passed through.
  bool intersect(const Ray& ray, float tMin, float tMax, const FaceClipSets& clips, Hit& hit) const {
    return closest(
        ray, tMin, tMax, [&](std::uint32_t face, float t) { return clips.keeps(ray, face, t); }, hit);
  }

  // Any hit with t in (tMin, tMax): the shadow-ray query, stops at the first blocker.
  bool occluded(const Ray& ray, float tMin, float tMax) const {
    for (const PackedTriangle& tri : triangles_) {
      if (intersectTriangle(tri, ray, tMin, tMax) >= 0.0f) return true;
    }
    return false;
  }
  // The same with removed faces casting no shadow.
  bool occluded(const Ray& ray, float tMin, float tMax, const FaceClipSets& clips) const {
    for (const PackedTriangle& tri : triangles_) {
      const float t = intersectTriangle(tri, ray, tMin, tMax);
      if (t >= 0.0f && clips.keeps(ray, tri.face, t)) return true;
    }
    return false;
  }

  std::size_t memoryBytes() const { return triangles_.capacity() * sizeof(PackedTriangle); }

 private:
  template <typename Keep>
  bool closest(const Ray& ray, float tMin, float tMax, Keep keep, Hit& hit) const {
    Hit best;
    best.t = tMax;
    for (const PackedTriangle& tri : triangles_) {
      // Upper bound one ulp past the best so an equal-t hit on a shared edge reaches the tie-break.
      const TriangleHit h = testTriangle(tri, ray, tMin, std::nextafter(best.t, INFINITY));
      if (h.t >= 0.0f && h.t < tMax && closerThan(h.t, tri.face, best) && keep(tri.face, h.t)) {
        best = {h.t, tri.face, h.b1, h.b2};
      }
    }
    if (!best.valid()) return false;
    hit = best;
    return true;
  }

  std::vector<PackedTriangle> triangles_;
};

}  // namespace lancer
