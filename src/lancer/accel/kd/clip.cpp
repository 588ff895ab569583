#include "lancer/accel/kd/clip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace lancer {

namespace {

// A convex polygon during Sutherland-Hodgman clipping; a triangle clipped by 6 planes has at
// most 3 + 6 corners. Plain arrays: Vec3d's operator[] is a select chain, which made this loop,
// indexed by a run-time axis, twice as slow.
struct Polygon {
  double corner[9][3];
  int count = 0;
};

// Keeps the part of `in` with sign * (p[axis] - plane) >= 0.
void clipAgainst(const Polygon& in, int axis, double plane, double sign, Polygon& out) {
  out.count = 0;
  if (in.count == 0) return;
  const double* a = in.corner[in.count - 1];
  double da = sign * (a[axis] - plane);
  for (int i = 0; i < in.count; ++i) {
    const double* b = in.corner[i];
    const double db = sign * (b[axis] - plane);
    // Edge a -> b: emit its crossing with the plane, then b if kept.
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const double s = da / (da - db);
      double* p = out.corner[out.count++];
      for (int k = 0; k < 3; ++k) p[k] = a[k] + (b[k] - a[k]) * s;
      p[axis] = plane;  // exactly on the plane, whatever the rounding of the interpolation
    }
    if (db >= 0) {
      double* p = out.corner[out.count++];
      p[0] = b[0];
      p[1] = b[1];
      p[2] = b[2];
    }
    a = b;
    da = db;
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
  for (int i = 0; i < 3; ++i) {
    a->corner[i][0] = corners[i].x;
    a->corner[i][1] = corners[i].y;
    a->corner[i][2] = corners[i].z;
  }
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
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k) lower[k] = upper[k] = a->corner[0][k];
  for (int i = 1; i < a->count; ++i) {
    for (int k = 0; k < 3; ++k) {
      lower[k] = std::min(lower[k], a->corner[i][k]);
      upper[k] = std::max(upper[k], a->corner[i][k]);
    }
  }
  Aabb result;
  for (int axis = 0; axis < 3; ++axis) {
    result.lower[axis] = std::max(roundDown(lower[axis]), box.lower[axis]);
    result.upper[axis] = std::min(roundUp(upper[axis]), box.upper[axis]);
  }
  return result;
}

void splitTriangleBounds(const std::array<Vec3, 3>& corners, int axis, float plane, Aabb& below,
                         Aabb& above) {
  double v[3][3], d[3];
  for (int i = 0; i < 3; ++i) {
    v[i][0] = corners[i].x;
    v[i][1] = corners[i].y;
    v[i][2] = corners[i].z;
    d[i] = v[i][axis] - double(plane);  // exact: a difference of two floats
  }
  constexpr double kHuge = std::numeric_limits<double>::infinity();
  double lower[2][3] = {{kHuge, kHuge, kHuge}, {kHuge, kHuge, kHuge}};
  double upper[2][3] = {{-kHuge, -kHuge, -kHuge}, {-kHuge, -kHuge, -kHuge}};
  auto extend = [&](int side, const double* p) {
    for (int k = 0; k < 3; ++k) {
      lower[side][k] = std::min(lower[side][k], p[k]);
      upper[side][k] = std::max(upper[side][k], p[k]);
    }
  };
  for (int i = 0; i < 3; ++i) {
    if (d[i] <= 0) extend(0, v[i]);
    if (d[i] >= 0) extend(1, v[i]);
    const int j = (i + 1) % 3;
    if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0)) {
      const double s = d[i] / (d[i] - d[j]);
      double p[3];
      for (int k = 0; k < 3; ++k) p[k] = v[i][k] + (v[j][k] - v[i][k]) * s;
      p[axis] = plane;  // exactly on the plane, whatever the rounding of the interpolation
      extend(0, p);
      extend(1, p);
    }
  }
  Aabb* out[2] = {&below, &above};
  for (int side = 0; side < 2; ++side) {
    *out[side] = Aabb{};
    if (!(lower[side][0] <= upper[side][0])) continue;  // no corner or crossing on this side
    for (int k = 0; k < 3; ++k) {
      out[side]->lower[k] = roundDown(lower[side][k]);
      out[side]->upper[k] = roundUp(upper[side][k]);
    }
  }
}

}  // namespace lancer
