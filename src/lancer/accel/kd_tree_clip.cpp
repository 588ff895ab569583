#include "lancer/accel/kd_tree_clip.hpp"

#include <cmath>
#include <utility>
#include <limits>

namespace lancer {

namespace {

// A convex polygon during Sutherland-Hodgman clipping; a triangle clipped by 6 planes has at
// most 3 + 6 corners.
struct Polygon {
  Vec3d corner[9];
  int count = 0;
};

// Keeps the part of `in` with sign * (p[axis] - plane) >= 0.
void clipAgainst(const Polygon& in, int axis, double plane, double sign, Polygon& out) {
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const Vec3d& a = in.corner[i];
    const Vec3d& b = in.corner[(i + 1) % in.count];
    const double da = sign * (a[axis] - plane);
    const double db = sign * (b[axis] - plane);
    if (da >= 0) out.corner[out.count++] = a;
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const double s = da / (da - db);
      Vec3d p = a + (b - a) * s;
      p[axis] = plane;  // exactly on the plane, whatever the rounding of the interpolation
      out.corner[out.count++] = p;
    }
  }
}

// Directed rounding to float. Exact values (corners, points on a cell's planes) stay exact: a
// bound one ulp past a shared vertex would make every split through that vertex duplicate the
// triangle into the neighbouring cell.
float roundDown(double value) {
  const auto f = static_cast<float>(value);
  return double(f) > value ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float roundUp(double value) {
  const auto f = static_cast<float>(value);
  return double(f) < value ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace

Aabb clippedTriangleBounds(const std::array<Vec3, 3>& corners, const Aabb& box) {
  // Ping-pong between two polygons by pointer: swapping the 220-byte structs cost more than clipping.
  Polygon buffers[2];
  Polygon* a = &buffers[0];
  Polygon* b = &buffers[1];
  a->count = 3;
  for (int i = 0; i < 3; ++i) a->corner[i] = toDouble(corners[i]);
  Aabb triangle;
  for (const Vec3& c : corners) triangle.extend(c);
  // Only the planes the triangle crosses cut anything; usually just the new split plane.
  for (int axis = 0; axis < 3; ++axis) {
    if (triangle.lower[axis] < box.lower[axis]) {
      clipAgainst(*a, axis, box.lower[axis], 1.0, *b);
      std::swap(a, b);
    }
    if (triangle.upper[axis] > box.upper[axis]) {
      clipAgainst(*a, axis, box.upper[axis], -1.0, *b);
      std::swap(a, b);
    }
    if (a->count == 0) return Aabb{};
  }
  Aabbd exact;
  for (int i = 0; i < a->count; ++i) exact.extend(a->corner[i]);
  Aabb result;
  for (int axis = 0; axis < 3; ++axis) {
    result.lower[axis] = std::max(roundDown(exact.lower[axis]), box.lower[axis]);
    result.upper[axis] = std::min(roundUp(exact.upper[axis]), box.upper[axis]);
  }
  return result;
}

}  // namespace lancer
