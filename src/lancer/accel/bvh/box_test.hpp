// The BVH's ray/box test: one ray against a node's eight child boxes in one AVX2 step (slabs,
// Kay & Kajiya), each box grown by a band against rounding as the kd-tree's split planes are
// (hit_query.hpp: kPlaneSlack), so that no hit the triangle test accepts lies outside the boxes that
// lead to it. Shared by the single-ray and packet walks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "lancer/accel/bvh/node.hpp"
#include "lancer/accel/hit_query.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/util/isa.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define LANCER_BVH_AVX2 1
#endif

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::bvh {
inline namespace LANCER_ISA_NS {

// A ray as the box test wants it: per axis the origin moved by the band towards the near side
// (nearEdge) and the far side (farEdge), so (plane - edge) * invDirection is where the ray meets
// the grown box; and whether it runs towards -axis (then a box's near plane is its upper one).
struct BoxRay {
  float nearEdge[3], farEdge[3], invDirection[3];
  int towardsMinus[3];

  BoxRay(const Ray& ray, float magnitude) {
    const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float inv[3] = {ray.invDirection.x, ray.invDirection.y, ray.invDirection.z};
    const float band = accel::kPlaneSlack * std::max(magnitude, maxComponent(abs(ray.origin)));
    for (int a = 0; a < 3; ++a) {
      towardsMinus[a] = inv[a] < 0.0f ? 1 : 0;
      const float signedBand = towardsMinus[a] ? -band : band;
      nearEdge[a] = origin[a] + signedBand;
      farEdge[a] = origin[a] - signedBand;
      invDirection[a] = inv[a];
    }
  }
};

#ifdef LANCER_BVH_AVX2

struct BoxRay8 {
  __m256 nearEdge[3], farEdge[3], invDirection[3];
  int nearIsUpper[3];

  explicit BoxRay8(const BoxRay& r) {
    for (int a = 0; a < 3; ++a) {
      nearEdge[a] = _mm256_set1_ps(r.nearEdge[a]);
      farEdge[a] = _mm256_set1_ps(r.farEdge[a]);
      invDirection[a] = _mm256_set1_ps(r.invDirection[a]);
      nearIsUpper[a] = r.towardsMinus[a];
    }
  }
};

// The children whose grown box the ray meets within [tMin, tFar], with where it enters each. A NaN
// (0 * inf: a ray parallel to a slab, on its plane) never narrows the span (maxps and minps return
// their second operand then).
inline std::uint32_t hitChildren(const BvhNode& node, const BoxRay8& r, __m256 tMin, __m256 tFar,
                                 __m256& tNear) {
  __m256 enter = tMin, exit = tFar;
  for (int a = 0; a < 3; ++a) {
    const float* nearPlane = r.nearIsUpper[a] ? node.upper[a] : node.lower[a];
    const float* farPlane = r.nearIsUpper[a] ? node.lower[a] : node.upper[a];
    const __m256 t0 =
        _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(nearPlane), r.nearEdge[a]), r.invDirection[a]);
    const __m256 t1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(farPlane), r.farEdge[a]), r.invDirection[a]);
    enter = _mm256_max_ps(t0, enter);
    exit = _mm256_min_ps(t1, exit);
  }
  tNear = enter;
  return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(enter, exit, _CMP_LE_OQ)));
}

#endif

// The same, one child at a time (builds without AVX2).
inline std::uint32_t hitChildrenScalar(const BvhNode& node, const BoxRay& r, float tMin, float tFar,
                                       float* tNear) {
  std::uint32_t mask = 0;
  for (int k = 0; k < BvhNode::kWidth; ++k) {
    float enter = tMin, exit = tFar;
    for (int a = 0; a < 3; ++a) {
      const float nearPlane = r.towardsMinus[a] ? node.upper[a][k] : node.lower[a][k];
      const float farPlane = r.towardsMinus[a] ? node.lower[a][k] : node.upper[a][k];
      const float t0 = (nearPlane - r.nearEdge[a]) * r.invDirection[a];
      const float t1 = (farPlane - r.farEdge[a]) * r.invDirection[a];
      enter = t0 > enter ? t0 : enter;
      exit = t1 < exit ? t1 : exit;
    }
    tNear[k] = enter;
    mask |= enter <= exit ? 1u << k : 0u;
  }
  return mask;
}

}  // namespace LANCER_ISA_NS
}  // namespace lancer::bvh
