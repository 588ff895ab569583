// What every tree's traversal shares (bvh/, kd/): the slack of its box and cell decisions, the
// closest-hit and any-hit bookkeeping, and the leaves' eight-triangle test, so that single rays and
// packets of every accelerator agree with the brute-force reference to the bit.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "lancer/accel/hit.hpp"
#include "lancer/accel/hit_filter.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/util/isa.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define LANCER_LEAF_AVX2 1
#endif

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::accel {
inline namespace LANCER_ISA_NS {

// Relative slack of the cell decisions, against the rounding of split distances and triangle hits.
constexpr float kSlack = 1e-6f;

// Half-width of the band around a split plane within which a ray counts as on both sides,
// relative to the largest coordinate involved: the triangle test accepts hits a few ulps outside a
// triangle (closed edges plus rounding), so a triangle that ends exactly at a plane can be hit by a
// ray that runs a hair beyond it, in the neighbouring cell.
constexpr float kPlaneSlack = 4e-6f;

// The next float up: the closest hit found so far still accepts an equal-t hit on a lower face.
inline float nextUp(float t) {
  if (!(t < std::numeric_limits<float>::infinity())) return t;
  if (t == 0.0f) return std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(t);
  return std::bit_cast<float>(t > 0.0f ? bits + 1 : bits - 1);
}

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
  // The rest of test, for a triangle of `face` whose sheared corners passed the float half (the
  // leaves' eight-triangle tests).
  bool finish(std::uint32_t face, const Ray& ray, float tMin, float tMax, float ax, float ay, float az,
              float bx, float by, float bz, float cx, float cy, float cz) {
    const TriangleHit h =
        triangle_detail::finishHit(ax, ay, az, bx, by, bz, cx, cy, cz, ray.shearZ, tMin, upper);
    takeIfCloser(h, face, ray, tMax, keeps, best, upper);
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
  bool finish(std::uint32_t face, const Ray& ray, float tMin, float tMax, float ax, float ay, float az,
              float bx, float by, float bz, float cx, float cy, float cz) const {
    const float t = triangle_detail::finishHit(ax, ay, az, bx, by, bz, cx, cy, cz, ray.shearZ, tMin, tMax).t;
    return t >= 0.0f && keeps(ray, face, t);
  }
  float bound(float tMax) const { return tMax; }
};

#ifdef LANCER_LEAF_AVX2

// Leaves this size or larger have their triangles tested eight at a time against one ray (the
// single-ray walks, and a kd packet lane left alone in a subtree); below it
// loading and transposing them costs more than the scalar tests they replace.
constexpr std::uint32_t kMinSimdLeaf = 3;

// Sheared corners in eight lanes, exactly as testTriangle computes them (the same operations on the
// same floats, no contraction), for finishing the test of the lanes whose edge functions agree in
// sign: up to eight triangles against one ray (lane i: triangle i), or one triangle against a
// packet's eight rays (accel/packet_frame.hpp).
struct LeafCorners {
  alignas(32) float ax[8], ay[8], az[8], bx[8], by[8], bz[8], cx[8], cy[8], cz[8];
};

// a b - c d as triangle_detail::differenceOfProducts computes it (Kahan's algorithm with FMA).
inline __m256 differenceOfProducts8(__m256 a, __m256 b, __m256 c, __m256 d) {
  const __m256 cd = _mm256_mul_ps(c, d);
  const __m256 cdError = _mm256_fnmadd_ps(c, d, cd);
  return _mm256_add_ps(_mm256_fmsub_ps(a, b, cd), cdError);
}

// The lanes of `lanes` whose edge functions u, v, w agree in sign (zero agrees with either), as
// testTriangle's float test decides; when there are any, the sheared corners are kept in `out` for
// the double finish. Shared by the leaf test below and the packet test (accel/packet_frame.hpp).
inline std::uint32_t keepSameSignLanes(__m256 u, __m256 v, __m256 w, std::uint32_t lanes, __m256 ax,
                                       __m256 ay, __m256 az, __m256 bx, __m256 by, __m256 bz, __m256 cx,
                                       __m256 cy, __m256 cz, LeafCorners& out) {
  const __m256 zero = _mm256_setzero_ps();
  const __m256 allNonNegative =
      _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(u, zero, _CMP_GE_OQ), _mm256_cmp_ps(v, zero, _CMP_GE_OQ)),
                    _mm256_cmp_ps(w, zero, _CMP_GE_OQ));
  const __m256 allNonPositive =
      _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(u, zero, _CMP_LE_OQ), _mm256_cmp_ps(v, zero, _CMP_LE_OQ)),
                    _mm256_cmp_ps(w, zero, _CMP_LE_OQ));
  const std::uint32_t passed =
      static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_or_ps(allNonNegative, allNonPositive))) & lanes;
  if (passed != 0) {
    _mm256_store_ps(out.ax, ax);
    _mm256_store_ps(out.ay, ay);
    _mm256_store_ps(out.az, az);
    _mm256_store_ps(out.bx, bx);
    _mm256_store_ps(out.by, by);
    _mm256_store_ps(out.bz, bz);
    _mm256_store_ps(out.cx, cx);
    _mm256_store_ps(out.cy, cy);
    _mm256_store_ps(out.cz, cz);
  }
  return passed;
}

// The float half of testTriangle for `count` (1..8) triangles given as one register per corner
// coordinate (coordinate[3 c + axis]: corner c's `axis` of lane i's triangle), against one ray.
inline std::uint32_t sameSignCorners(const __m256 (&coordinate)[9], std::uint32_t count, const Ray& ray,
                                     LeafCorners& out) {
  const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  // Corner c's coordinate along `axis`, minus the origin's (testTriangle's da, db, dc).
  auto corner = [&](int c, int axis) {
    return _mm256_sub_ps(coordinate[3 * c + axis], _mm256_set1_ps(origin[axis]));
  };
  const __m256 shearX = _mm256_set1_ps(ray.shearX), shearY = _mm256_set1_ps(ray.shearY);
  const __m256 az = corner(0, ray.kz), bz = corner(1, ray.kz), cz = corner(2, ray.kz);
  const __m256 ax = _mm256_fnmadd_ps(shearX, az, corner(0, ray.kx));
  const __m256 ay = _mm256_fnmadd_ps(shearY, az, corner(0, ray.ky));
  const __m256 bx = _mm256_fnmadd_ps(shearX, bz, corner(1, ray.kx));
  const __m256 by = _mm256_fnmadd_ps(shearY, bz, corner(1, ray.ky));
  const __m256 cx = _mm256_fnmadd_ps(shearX, cz, corner(2, ray.kx));
  const __m256 cy = _mm256_fnmadd_ps(shearY, cz, corner(2, ray.ky));
  const __m256 u = differenceOfProducts8(cx, by, cy, bx);
  const __m256 v = differenceOfProducts8(ax, cy, ay, cx);
  const __m256 w = differenceOfProducts8(bx, ay, by, ax);
  return keepSameSignLanes(u, v, w, (1u << count) - 1u, ax, ay, az, bx, by, bz, cx, cy, cz, out);
}

// The float half of testTriangle for `count` (1..8) triangles `tri` (each a PackedTriangle's first
// float; all eight readable, the ones past `count` repeats), against one ray: the lanes whose ray line
// meets the triangle. Shared by the kd-tree's and the BVH's leaves.
inline std::uint32_t sameSignTriangles(const float* const (&tri)[8], std::uint32_t count, const Ray& ray,
                                       LeafCorners& out) {
  static_assert(offsetof(PackedTriangle, v0) == 0 && offsetof(PackedTriangle, v2) == 6 * sizeof(float) &&
                sizeof(Vec3) == 3 * sizeof(float));
  // The triangles' first eight floats (v0, v1, v2.x, v2.y) as the rows of an 8x8 matrix, transposed
  // to one register per coordinate (unpack, shuffle, then swap halves); gathers measured slower.
  __m256 row[8];
  for (int i = 0; i < 8; ++i) row[i] = _mm256_loadu_ps(tri[i]);
  __m256 coordinate[9];
  for (int half = 0; half < 2; ++half) {
    const __m256* r = row + 4 * half;
    const __m256 lo01 = _mm256_unpacklo_ps(r[0], r[1]), hi01 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 lo23 = _mm256_unpacklo_ps(r[2], r[3]), hi23 = _mm256_unpackhi_ps(r[2], r[3]);
    // Coordinates k and k + 4 of triangles 4 half .. 4 half + 3.
    __m256* q = row + 4 * half;
    q[0] = _mm256_shuffle_ps(lo01, lo23, _MM_SHUFFLE(1, 0, 1, 0));
    q[1] = _mm256_shuffle_ps(lo01, lo23, _MM_SHUFFLE(3, 2, 3, 2));
    q[2] = _mm256_shuffle_ps(hi01, hi23, _MM_SHUFFLE(1, 0, 1, 0));
    q[3] = _mm256_shuffle_ps(hi01, hi23, _MM_SHUFFLE(3, 2, 3, 2));
  }
  for (int k = 0; k < 4; ++k) {
    coordinate[k] = _mm256_permute2f128_ps(row[k], row[4 + k], 0x20);
    coordinate[4 + k] = _mm256_permute2f128_ps(row[k], row[4 + k], 0x31);
  }
  coordinate[8] =
      _mm256_set_ps(tri[7][8], tri[6][8], tri[5][8], tri[4][8], tri[3][8], tri[2][8], tri[1][8], tri[0][8]);
  return sameSignCorners(coordinate, count, ray, out);
}

#endif  // LANCER_LEAF_AVX2

}  // namespace LANCER_ISA_NS
}  // namespace lancer::accel
