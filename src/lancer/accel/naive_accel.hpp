// The brief's first algorithm: test every triangle. Slow (linear in faces) but obviously right,
// it is the reference that the kd-tree is checked against.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/triangle_intersect.hpp"

namespace lancer {

class NaiveAccel {
 public:
  NaiveAccel(std::span<const Vec3> positions, std::span<const MeshFace> faces)
      : triangles_(packTriangles(positions, faces)) {}

  // Closest hit with t in (tMin, tMax); returns false (hit untouched) when there is none.
  bool intersect(const Ray& ray, float tMin, float tMax, Hit& hit) const {
    Hit best;
    best.t = tMax;
    for (const PackedTriangle& tri : triangles_) {
      // Upper bound one ulp past the best so an equal-t hit on a shared edge reaches the tie-break.
      const float t = intersectTriangle(tri, ray, tMin, std::nextafter(best.t, INFINITY));
      if (t >= 0.0f && t < tMax && closerThan(t, tri.face, best)) {
        best.t = t;
        best.face = tri.face;
      }
    }
    if (!best.valid()) return false;
    hit = best;
    return true;
  }

  // Any hit with t in (tMin, tMax): the shadow-ray query, stops at the first blocker.
  bool occluded(const Ray& ray, float tMin, float tMax) const {
    for (const PackedTriangle& tri : triangles_) {
      if (intersectTriangle(tri, ray, tMin, tMax) >= 0.0f) return true;
    }
    return false;
  }

  std::size_t memoryBytes() const { return triangles_.capacity() * sizeof(PackedTriangle); }

 private:
  std::vector<PackedTriangle> triangles_;
};

}  // namespace lancer
