#include "lancer/mesh/face_terms.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/math/fast_acos.hpp"
#include "lancer/mesh/face_geometry.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

namespace lancer {
namespace {

#if defined(__AVX2__) && defined(__FMA__)

// Eight vectors, one per lane.
struct Lanes3 {
  __m256 x, y, z;
};

Lanes3 minus(const Lanes3& a, const Lanes3& b) {
  return {_mm256_sub_ps(a.x, b.x), _mm256_sub_ps(a.y, b.y), _mm256_sub_ps(a.z, b.z)};
}

__m256 dot(const Lanes3& a, const Lanes3& b) {
  return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a.x, b.x), _mm256_mul_ps(a.y, b.y)),
                       _mm256_mul_ps(a.z, b.z));
}

// As normalize (vec3.hpp): a zero vector stays zero.
Lanes3 normalized(const Lanes3& a) {
  const __m256 length = _mm256_sqrt_ps(dot(a, a));
  const __m256 inverse = _mm256_div_ps(_mm256_set1_ps(1.0f), length);
  const __m256 positive = _mm256_cmp_ps(length, _mm256_setzero_ps(), _CMP_GT_OQ);
  return {_mm256_blendv_ps(a.x, _mm256_mul_ps(a.x, inverse), positive),
          _mm256_blendv_ps(a.y, _mm256_mul_ps(a.y, inverse), positive),
          _mm256_blendv_ps(a.z, _mm256_mul_ps(a.z, inverse), positive)};
}

// fastAcos (fast_acos.hpp) in eight lanes, of x clamped to [-1, 1].
__m256 fastAcos8(__m256 x) {
  x = _mm256_max_ps(_mm256_min_ps(x, _mm256_set1_ps(1.0f)), _mm256_set1_ps(-1.0f));
  const __m256 a = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), x);
  const __m256 wide = _mm256_cmp_ps(a, _mm256_set1_ps(0.5f), _CMP_GT_OQ);
  const __m256 z = _mm256_blendv_ps(
      _mm256_mul_ps(a, a), _mm256_mul_ps(_mm256_set1_ps(0.5f), _mm256_sub_ps(_mm256_set1_ps(1.0f), a)), wide);
  const __m256 s = _mm256_blendv_ps(a, _mm256_sqrt_ps(z), wide);
  __m256 p = _mm256_fmadd_ps(_mm256_set1_ps(4.2163199048e-2f), z, _mm256_set1_ps(2.4181311049e-2f));
  p = _mm256_fmadd_ps(p, z, _mm256_set1_ps(4.5470025998e-2f));
  p = _mm256_fmadd_ps(p, z, _mm256_set1_ps(7.4953002686e-2f));
  p = _mm256_fmadd_ps(p, z, _mm256_set1_ps(1.6666752422e-1f));
  const __m256 asinS = _mm256_fmadd_ps(_mm256_mul_ps(p, z), s, s);
  const __m256 acosA = _mm256_blendv_ps(_mm256_sub_ps(_mm256_set1_ps(1.5707963267948966f), asinS),
                                        _mm256_mul_ps(_mm256_set1_ps(2.0f), asinS), wide);
  const __m256 negative = _mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_LT_OQ);
  return _mm256_blendv_ps(acosA, _mm256_sub_ps(_mm256_set1_ps(3.14159265358979f), acosA), negative);
}

Lanes3 crossOf(const Lanes3& a, const Lanes3& b) {
  return {_mm256_sub_ps(_mm256_mul_ps(a.y, b.z), _mm256_mul_ps(a.z, b.y)),
          _mm256_sub_ps(_mm256_mul_ps(a.z, b.x), _mm256_mul_ps(a.x, b.z)),
          _mm256_sub_ps(_mm256_mul_ps(a.x, b.y), _mm256_mul_ps(a.y, b.x))};
}

Lanes3 select(const Lanes3& ifZero, const Lanes3& ifSet, __m256 mask) {
  return {_mm256_blendv_ps(ifZero.x, ifSet.x, mask), _mm256_blendv_ps(ifZero.y, ifSet.y, mask),
          _mm256_blendv_ps(ifZero.z, ifSet.z, mask)};
}

// Up to eight faces (count >= 1); the lanes past count repeat the last face. False when a face may
// be degenerate: twice its area is not clearly above float rounding.
bool faceTermsOfBlock(const Vec3* positions, const MeshFace* faces, std::size_t count, Vec3* normals,
                      std::array<float, 4>* angles) {
  // Corner k of each lane; a triangle's fourth corner is its first, so that the edge into it closes
  // the triangle (its own angle is dropped).
  alignas(32) float corner[4][3][8];
  alignas(32) float quad[8];
  for (std::size_t lane = 0; lane < 8; ++lane) {
    const MeshFace& face = faces[std::min(lane, count - 1)];
    const bool isQuad = face.isQuad();
    quad[lane] = isQuad ? -1.0f : 0.0f;  // the sign bit selects in blendv
    for (int k = 0; k < 4; ++k) {
      const Vec3& p = positions[face.vertex[k == 3 && !isQuad ? 0 : k]];
      corner[k][0][lane] = p.x;
      corner[k][1][lane] = p.y;
      corner[k][2][lane] = p.z;
    }
  }
  Lanes3 q[4];
  for (int k = 0; k < 4; ++k)
    q[k] = {_mm256_load_ps(corner[k][0]), _mm256_load_ps(corner[k][1]), _mm256_load_ps(corner[k][2])};
  const __m256 isQuad = _mm256_load_ps(quad);
  // The face's normal: a triangle's (b - a) x (c - a), a quad's diagonals (c - a) x (d - b).
  const Lanes3 twiceArea = crossOf(select(minus(q[1], q[0]), minus(q[2], q[0]), isQuad),
                                   select(minus(q[2], q[0]), minus(q[3], q[1]), isQuad));
  const Lanes3 normal = normalized(twiceArea);
  // Clearly not degenerate: twice the area above 1e-5 of the longest edge squared, where float
  // rounding is 1e-7 of it and isDegenerateFace's line 1e-12. A face under it may be kept by a
  // build (which tests the mesh's own frame, in double) or not: the caller builds again.
  const Lanes3 edge[4] = {minus(q[1], q[0]), minus(q[2], q[1]), minus(q[3], q[2]), minus(q[0], q[3])};
  __m256 longest = _mm256_max_ps(_mm256_max_ps(dot(edge[0], edge[0]), dot(edge[1], edge[1])),
                                 _mm256_max_ps(dot(edge[2], edge[2]), dot(edge[3], edge[3])));
  const __m256 areaSquared = dot(twiceArea, twiceArea);
  const __m256 clear = _mm256_cmp_ps(
      areaSquared, _mm256_mul_ps(_mm256_set1_ps(1e-10f), _mm256_mul_ps(longest, longest)), _CMP_GT_OQ);
  const int clearLanes = _mm256_movemask_ps(clear);
  // out[k]: the unit edge from corner k to the next (a triangle's third: to its first).
  const Lanes3 out[4] = {normalized(edge[0]), normalized(edge[1]), normalized(edge[2]), normalized(edge[3])};
  // The angle at corner k between its edge out and the reverse of the edge in: acos(-dot(out, in)).
  const Lanes3 intoFirst{_mm256_blendv_ps(out[2].x, out[3].x, isQuad),
                         _mm256_blendv_ps(out[2].y, out[3].y, isQuad),
                         _mm256_blendv_ps(out[2].z, out[3].z, isQuad)};
  const __m256 sign = _mm256_set1_ps(-0.0f);
  alignas(32) float angle[4][8];
  _mm256_store_ps(angle[0], fastAcos8(_mm256_xor_ps(sign, dot(out[0], intoFirst))));
  _mm256_store_ps(angle[1], fastAcos8(_mm256_xor_ps(sign, dot(out[1], out[0]))));
  _mm256_store_ps(angle[2], fastAcos8(_mm256_xor_ps(sign, dot(out[2], out[1]))));
  _mm256_store_ps(angle[3], _mm256_blendv_ps(_mm256_setzero_ps(),
                                             fastAcos8(_mm256_xor_ps(sign, dot(out[3], out[2]))), isQuad));
  alignas(32) float n[3][8];
  _mm256_store_ps(n[0], normal.x);
  _mm256_store_ps(n[1], normal.y);
  _mm256_store_ps(n[2], normal.z);
  for (std::size_t lane = 0; lane < count; ++lane) {
    angles[lane] = {angle[0][lane], angle[1][lane], angle[2][lane], angle[3][lane]};
    normals[lane] = {n[0][lane], n[1][lane], n[2][lane]};
  }
  const int used = (1 << count) - 1;
  return (clearLanes & used) == used;
}

#else

// The vector path's test: twice the area above 1e-5 of the longest edge squared.
bool clearlyNotDegenerate(const Vec3* p, const MeshFace& face) {
  const Vec3& a = p[face.vertex[0]];
  const Vec3& b = p[face.vertex[1]];
  const Vec3& c = p[face.vertex[2]];
  const Vec3& d = face.isQuad() ? p[face.vertex[3]] : a;
  const Vec3 twiceArea = face.isQuad() ? cross(c - a, d - b) : cross(b - a, c - a);
  const float longest = std::max(std::max(dot(b - a, b - a), dot(c - b, c - b)),
                                 std::max(dot(d - c, d - c), dot(a - d, a - d)));
  return dot(twiceArea, twiceArea) > 1e-10f * longest * longest;
}

// Each edge is normalised once and shared by the two corners at its ends (the edge into a corner
// is the reverse of the one out of the previous corner, and negation is exact, so the angles are
// the same bits as from each corner's own two edges).
std::array<float, 4> cornerAnglesOfFace(const Vec3* positions, const MeshFace& face) {
  const int n = face.cornerCount();
  Vec3 out[4];  // out[c]: unit edge from corner c to corner c + 1
  for (int c = 0; c < n; ++c)
    out[c] = normalize(positions[face.vertex[(c + 1) % n]] - positions[face.vertex[c]]);
  std::array<float, 4> angle{0, 0, 0, 0};
  for (int c = 0; c < n; ++c)
    angle[c] = fastAcos(std::clamp(dot(out[c], -out[(c + n - 1) % n]), -1.0f, 1.0f));
  return angle;
}

#endif

}  // namespace

template <typename Isa>
bool faceTermsOn(std::span<const Vec3> positions, std::span<const MeshFace> faces, Vec3* normals,
                 std::array<float, 4>* angles) {
  bool clear = true;
#if defined(__AVX2__) && defined(__FMA__)
  for (std::size_t first = 0; first < faces.size(); first += 8)
    clear &=
        faceTermsOfBlock(positions.data(), faces.data() + first,
                         std::min<std::size_t>(8, faces.size() - first), normals + first, angles + first);
#else
  for (std::size_t f = 0; f < faces.size(); ++f) {
    normals[f] = faceNormal(positions, faces[f]);
    angles[f] = cornerAnglesOfFace(positions.data(), faces[f]);
    clear = clear && clearlyNotDegenerate(positions.data(), faces[f]);
  }
#endif
  return clear;
}

template bool faceTermsOn<LANCER_ISA_TAG>(std::span<const Vec3>, std::span<const MeshFace>, Vec3*,
                                          std::array<float, 4>*);

}  // namespace lancer
