#include "lancer/accel/kd/clip.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

// The float next to a finite f towards -inf / +inf: std::nextafter's result, without its call
// (the clippers round a dozen bounds a triangle, about half of them the wrong way first).
float nextDown(float f) {
  const auto bits = std::bit_cast<std::uint32_t>(f);
  return f > 0.0f   ? std::bit_cast<float>(bits - 1)
         : f < 0.0f ? std::bit_cast<float>(bits + 1)
                    : -std::numeric_limits<float>::denorm_min();
}

float nextUp(float f) {
  const auto bits = std::bit_cast<std::uint32_t>(f);
  return f > 0.0f   ? std::bit_cast<float>(bits + 1)
         : f < 0.0f ? std::bit_cast<float>(bits - 1)
                    : std::numeric_limits<float>::denorm_min();
}

// Directed rounding to float. Exact values (corners, points on a cell's planes) stay exact: a
// bound one ulp past a shared vertex would make every split through that vertex duplicate the
// triangle into the neighbouring cell.
float roundDown(double value) {
  const auto f = static_cast<float>(value);
  return double(f) > value ? nextDown(f) : f;
}

float roundUp(double value) {
  const auto f = static_cast<float>(value);
  return double(f) < value ? nextUp(f) : f;
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

#if defined(__AVX2__)
namespace {

// A mask of four doubles as a mask of four floats.
__m128 wrongWay(__m256d mask) {
  const __m256i low =
      _mm256_permutevar8x32_epi32(_mm256_castpd_si256(mask), _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7));
  return _mm_castsi128_ps(_mm256_castsi256_si128(low));
}

// roundDown / roundUp of four doubles (the conversion rounds to nearest, as static_cast does).
__m128 roundDown4(__m256d value) {
  const __m128 f = _mm256_cvtpd_ps(value);
  const __m128 wrong = wrongWay(_mm256_cmp_pd(_mm256_cvtps_pd(f), value, _CMP_GT_OQ));
  if (_mm_movemask_ps(wrong) == 0) return f;
  const __m128i bits = _mm_castps_si128(f);
  const __m128 zero = _mm_setzero_ps();
  __m128i down = _mm_set1_epi32(static_cast<int>(0x80000001u));  // -denorm_min, below +-0
  down = _mm_castps_si128(_mm_blendv_ps(_mm_castsi128_ps(down),
                                        _mm_castsi128_ps(_mm_sub_epi32(bits, _mm_set1_epi32(1))),
                                        _mm_cmpgt_ps(f, zero)));
  down = _mm_castps_si128(_mm_blendv_ps(_mm_castsi128_ps(down),
                                        _mm_castsi128_ps(_mm_add_epi32(bits, _mm_set1_epi32(1))),
                                        _mm_cmplt_ps(f, zero)));
  return _mm_blendv_ps(f, _mm_castsi128_ps(down), wrong);
}

// Up is down mirrored: negating is exact, and the float just above x is minus the one just below -x
// (+0 goes to -0 and back, a value that rounds to zero goes up to denorm_min).
__m128 roundUp4(__m256d value) {
  const __m128 mirrored = roundDown4(_mm256_xor_pd(value, _mm256_set1_pd(-0.0)));
  return _mm_xor_ps(mirrored, _mm_set1_ps(-0.0f));
}

}  // namespace

void splitTriangleBounds(const PackedTriangle& triangle, int axis, float plane, __m128 lower[2],
                         __m128 upper[2]) {
  static_assert(sizeof(Vec3) == 3 * sizeof(float) && offsetof(PackedTriangle, v1) == 12 &&
                offsetof(PackedTriangle, v2) == 24 && sizeof(PackedTriangle) >= 40);
  const float* corner = &triangle.v0.x;  // v0, v1, v2 contiguous; lane 3 of each load is ignored
  const __m256d v[3] = {_mm256_cvtps_pd(_mm_loadu_ps(corner)), _mm256_cvtps_pd(_mm_loadu_ps(corner + 3)),
                        _mm256_cvtps_pd(_mm_loadu_ps(corner + 6))};
  double d[3];
  for (int i = 0; i < 3; ++i) d[i] = double(corner[3 * i + axis]) - double(plane);  // exact
  const __m256d huge = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  __m256d lo[2] = {huge, huge}, hi[2] = {-huge, -huge};
  // min(x, lo) / max(x, hi) in this operand order are std::min(lo, x) / std::max(hi, x).
  auto extend = [&](int side, __m256d p) {
    lo[side] = _mm256_min_pd(p, lo[side]);
    hi[side] = _mm256_max_pd(p, hi[side]);
  };
  alignas(32) static constexpr std::int64_t kAxisLane[3][4] = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}};
  const __m256d onAxis = _mm256_load_pd(reinterpret_cast<const double*>(kAxisLane[axis]));
  const __m256d planeD = _mm256_set1_pd(double(plane));
  for (int i = 0; i < 3; ++i) {
    if (d[i] <= 0) extend(0, v[i]);
    if (d[i] >= 0) extend(1, v[i]);
    const int j = (i + 1) % 3;
    if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0)) {
      const __m256d s = _mm256_set1_pd(d[i] / (d[i] - d[j]));
      __m256d p = _mm256_fmadd_pd(_mm256_sub_pd(v[j], v[i]), s, v[i]);
      p = _mm256_blendv_pd(p, planeD, onAxis);  // exactly on the plane
      extend(0, p);
      extend(1, p);
    }
  }
  for (int side = 0; side < 2; ++side) {
    lower[side] = roundDown4(lo[side]);
    upper[side] = roundUp4(hi[side]);
  }
}
#endif

}  // namespace lancer
