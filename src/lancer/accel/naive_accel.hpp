// The simplest accelerator: test every triangle. Slow (linear in faces) but obviously right,
// it is the reference that every accelerator is checked against.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/hit_filter.hpp"
#include "lancer/accel/tree_queries.hpp"
#include "lancer/accel/triangle_intersect.hpp"

namespace lancer {

// Its packet queries are its single-ray ones, lane by lane.
class NaiveAccel : public TreeQueries<NaiveAccel> {
 public:
  NaiveAccel(std::span<const Vec3> positions, std::span<const MeshFace> faces)
      : triangles_(packTriangles(positions, faces)) {}

  std::size_t memoryBytes() const { return triangles_.capacity() * sizeof(PackedTriangle); }

  // The walks behind TreeQueries' eight queries, for any filter.
  template <typename Filter>
  bool anyHit(const Ray& ray, float tMin, float tMax, const Filter& keep) const {
    for (const PackedTriangle& tri : triangles_) {
      const float t = intersectTriangle(tri, ray, tMin, tMax);
      if (t >= 0.0f && keep(ray, tri.face, t)) return true;
    }
    return false;
  }
  template <typename Filter>
  bool closestHit(const Ray& ray, float tMin, float tMax, const Filter& keep, Hit& hit) const {
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
  template <typename Filter>
  std::uint32_t closestHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps,
                            std::span<Hit, kPacketSize> hits) const {
    return closestHitsOneByOne(packet, active & kAllLanes, keeps, hits);
  }
  template <typename Filter>
  std::uint32_t anyHits(const RayPacket& packet, std::uint32_t active, const Filter& keeps) const {
    return anyHitsOneByOne(packet, active & kAllLanes, keeps);
  }

 private:
  std::vector<PackedTriangle> triangles_;
};

}  // namespace lancer
