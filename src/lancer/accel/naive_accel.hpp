// The simplest accelerator: test every triangle. Slow (linear in faces) but obviously right,
// it is the reference that the kd-tree is checked against.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/hit_filter.hpp"
#include "lancer/accel/triangle_intersect.hpp"

namespace lancer {

class NaiveAccel {
 public:
  NaiveAccel(std::span<const Vec3> positions, std::span<const MeshFace> faces)
      : triangles_(packTriangles(positions, faces)) {}

  // Closest hit with t in (tMin, tMax); returns false (hit untouched) when there is none.
  bool intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const {
    return closest(ray, tMin, tMax, keepEveryHit, hit);
  }
  // The same among the hits `filter` keeps: a refused face is passed through.
  bool intersect(const Ray& ray, float tMin, float tMax, const HitFilter& filter, Hit& hit) const {
    return closest(ray, tMin, tMax, filter, hit);
  }

  // Any hit with t in (tMin, tMax): the shadow-ray query, stops at the first blocker.
  bool occluded(const Ray& ray, float tMin, float tMax) const { return any(ray, tMin, tMax, keepEveryHit); }
  // The same with refused faces casting no shadow.
  bool occluded(const Ray& ray, float tMin, float tMax, const HitFilter& filter) const {
    return any(ray, tMin, tMax, filter);
  }

  std::size_t memoryBytes() const { return triangles_.capacity() * sizeof(PackedTriangle); }

 private:
  static bool keepEveryHit(const Ray&, std::uint32_t, float) { return true; }

  template <typename Keep>
  bool any(const Ray& ray, float tMin, float tMax, const Keep& keep) const {
    for (const PackedTriangle& tri : triangles_) {
      const float t = intersectTriangle(tri, ray, tMin, tMax);
      if (t >= 0.0f && keep(ray, tri.face, t)) return true;
    }
    return false;
  }

  template <typename Keep>
  bool closest(const Ray& ray, float tMin, float tMax, const Keep& keep, Hit& hit) const {
    Hit best;
    best.t = tMax;
    for (const PackedTriangle& tri : triangles_) {
      // Upper bound one ulp past the best so an equal-t hit on a shared edge reaches the tie-break.
      const TriangleHit h = testTriangle(tri, ray, tMin, std::nextafter(best.t, INFINITY));
      if (h.t >= 0.0f && h.t < tMax && closerThan(h.t, tri.face, best) && keep(ray, tri.face, h.t)) {
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
