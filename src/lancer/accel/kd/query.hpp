// What the kd-tree traversals share: the slack of their cell decisions and the closest-hit and
// any-hit bookkeeping, so that single rays (traversal.cpp) and packets (packet_traversal.cpp) agree.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/ray.hpp"

namespace lancer::kd {

// Relative slack of the cell decisions, against the rounding of split distances and triangle hits.
constexpr float kSlack = 1e-6f;

// Half-width of the band around a split plane within which a ray counts as on both sides,
// relative to the largest coordinate involved: the triangle test accepts hits a few ulps outside a
// triangle (closed edges plus rounding), so a triangle that ends exactly at a plane can be hit by a
// ray that runs a hair beyond it, in the neighbouring cell.
constexpr float kPlaneSlack = 4e-6f;

// Recently tested triangles, direct-mapped by index: neighbouring leaves share triangles.
constexpr std::uint32_t kMailboxSize = 8;

// The next float up: the closest hit found so far still accepts an equal-t hit on a lower face.
inline float nextUp(float t) {
  if (!(t < std::numeric_limits<float>::infinity())) return t;
  if (t == 0.0f) return std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(t);
  return std::bit_cast<float>(t > 0.0f ? bits + 1 : bits - 1);
}

// Every hit counts: the filter of the unfiltered queries, compiled away.
struct KeepEveryHit {
  bool operator()(const Ray&, std::uint32_t, float) const { return true; }
};

// Takes hit `h` of `face` as `best` when it is closer (or tied on a lower face) and kept; `upper`
// becomes the bound of the next tests. Returns whether it did.
template <typename Filter>
inline bool takeIfCloser(const TriangleHit& h, std::uint32_t face, const Ray& ray, float tMax,
                         const Filter& keeps, Hit& best, float& upper) {
  if (!(h.t >= 0.0f && h.t < tMax && closerThan(h.t, face, best) && keeps(ray, face, h.t))) return false;
  best = {h.t, face, h.b1, h.b2};
  upper = nextUp(h.t);
  return true;
}

// Closest-hit bookkeeping identical to NaiveAccel::intersect. With a filter (per-mesh cut views), a
// hit it refuses is not a hit: pruning by the closest kept hit stays exact, and so does the mailbox
// (a repeated test of a triangle gets the same answer, kept or not).
template <typename Filter>
struct ClosestHit {
  static constexpr bool kAnyHit = false;
  Hit best;
  float upper;  // triangles are tested on (tMin, upper): t <= best.t once something was hit
  const Filter& keeps;

  bool test(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax) {
    takeIfCloser(testTriangle(tri, ray, tMin, upper), tri.face, ray, tMax, keeps, best, upper);
    return false;
  }
  // The rest of test, for a triangle whose sheared corners passed the float half (traversal.cpp).
  bool finish(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax, float ax, float ay, float az,
              float bx, float by, float bz, float cx, float cy, float cz) {
    const TriangleHit h =
        triangle_detail::finishHit(ax, ay, az, bx, by, bz, cx, cy, cz, ray.shearZ, tMin, upper);
    takeIfCloser(h, tri.face, ray, tMax, keeps, best, upper);
    return false;
  }
  float bound(float) const { return best.t; }
};

template <typename Filter>
struct AnyHit {
  static constexpr bool kAnyHit = true;
  const Filter& keeps;

  bool test(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax) const {
    const float t = intersectTriangle(tri, ray, tMin, tMax);
    return t >= 0.0f && keeps(ray, tri.face, t);
  }
  bool finish(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax, float ax, float ay, float az,
              float bx, float by, float bz, float cx, float cy, float cz) const {
    const float t = triangle_detail::finishHit(ax, ay, az, bx, by, bz, cx, cy, cz, ray.shearZ, tMin, tMax).t;
    return t >= 0.0f && keeps(ray, tri.face, t);
  }
  float bound(float tMax) const { return tMax; }
};

}  // namespace lancer::kd
