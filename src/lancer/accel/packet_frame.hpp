// The packet walks' SIMD view of a packet (bvh/packet_traversal.cpp, kd/packet_traversal.cpp): the
// rays as lanes of AVX2 registers (PacketFrame), the packet triangle test and the closest-hit and
// any-hit bookkeeping per lane, shared by both trees.
#pragma once

#include <bit>
#include <cstdint>
#include <span>

#include "lancer/accel/hit_query.hpp"
#include "lancer/accel/ray_packet.hpp"
#include "lancer/accel/triangle_intersect.hpp"
#include "lancer/math/aabb.hpp"
#include "lancer/util/isa.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#define LANCER_PACKETS_AVX2 1
#endif

// The copy of the kernels being compiled (util/isa.hpp).
namespace lancer::accel {
inline namespace LANCER_ISA_NS {

#ifdef LANCER_PACKETS_AVX2

inline std::uint32_t laneMask(__m256 condition) {
  return static_cast<std::uint32_t>(_mm256_movemask_ps(condition));
}

// Per lane, the component of (x, y, z) along the lane's axis (is0: axis 0, is1: axis 1, else 2).
inline __m256 pickAxis(__m256 x, __m256 y, __m256 z, __m256 is0, __m256 is1) {
  return _mm256_blendv_ps(_mm256_blendv_ps(z, y, is1), x, is0);
}

// A triangle's corners relative to each lane's origin in the lane's sheared frame (hit_query.hpp's
// eight-lane corners).
static_assert(kPacketSize == 8);
using ShearedCorners = LeafCorners;

// The packet's rays, lane i of each register being ray i.
struct PacketFrame {
  __m256 origin[3];
  __m256 invDirection[3];
  __m256 shearX, shearY;
  __m256 kxIs0, kxIs1, kyIs0, kyIs1, kzIs0, kzIs1;
  std::uint32_t firstIsRight[3];
  // Every lane has the same kx, ky, kz (coherent rays nearly always do): the triangle test picks
  // each corner's coordinates once instead of blending all three per lane.
  bool uniformAxes;
  int kx, ky, kz;
  alignas(32) float shearZ[kPacketSize];
};

// The lanes among `lanes` whose ray's line meets `tri` (the float half of testTriangle, bit for bit).
inline std::uint32_t sameSignLanes(const PackedTriangle& tri, const PacketFrame& f, std::uint32_t lanes,
                                   ShearedCorners& out) {
  static_assert(sizeof(Vec3) == 3 * sizeof(float));
  __m256 ax, ay, az, bx, by, bz, cx, cy, cz;
  if (f.uniformAxes) {
    // The same subtractions as below, only of the coordinates the blends would pick.
    const float* v0 = &tri.v0.x;
    const float* v1 = &tri.v1.x;
    const float* v2 = &tri.v2.x;
    auto relative = [&](const float* v, int axis) {
      return _mm256_sub_ps(_mm256_set1_ps(v[axis]), f.origin[axis]);
    };
    az = relative(v0, f.kz);
    bz = relative(v1, f.kz);
    cz = relative(v2, f.kz);
    ax = _mm256_fnmadd_ps(f.shearX, az, relative(v0, f.kx));
    ay = _mm256_fnmadd_ps(f.shearY, az, relative(v0, f.ky));
    bx = _mm256_fnmadd_ps(f.shearX, bz, relative(v1, f.kx));
    by = _mm256_fnmadd_ps(f.shearY, bz, relative(v1, f.ky));
    cx = _mm256_fnmadd_ps(f.shearX, cz, relative(v2, f.kx));
    cy = _mm256_fnmadd_ps(f.shearY, cz, relative(v2, f.ky));
  } else {
    const __m256 ax0 = _mm256_sub_ps(_mm256_set1_ps(tri.v0.x), f.origin[0]);
    const __m256 ay0 = _mm256_sub_ps(_mm256_set1_ps(tri.v0.y), f.origin[1]);
    const __m256 az0 = _mm256_sub_ps(_mm256_set1_ps(tri.v0.z), f.origin[2]);
    const __m256 bx0 = _mm256_sub_ps(_mm256_set1_ps(tri.v1.x), f.origin[0]);
    const __m256 by0 = _mm256_sub_ps(_mm256_set1_ps(tri.v1.y), f.origin[1]);
    const __m256 bz0 = _mm256_sub_ps(_mm256_set1_ps(tri.v1.z), f.origin[2]);
    const __m256 cx0 = _mm256_sub_ps(_mm256_set1_ps(tri.v2.x), f.origin[0]);
    const __m256 cy0 = _mm256_sub_ps(_mm256_set1_ps(tri.v2.y), f.origin[1]);
    const __m256 cz0 = _mm256_sub_ps(_mm256_set1_ps(tri.v2.z), f.origin[2]);
    az = pickAxis(ax0, ay0, az0, f.kzIs0, f.kzIs1);
    bz = pickAxis(bx0, by0, bz0, f.kzIs0, f.kzIs1);
    cz = pickAxis(cx0, cy0, cz0, f.kzIs0, f.kzIs1);
    // shear(x, s, z) = fma(-s, z, x)
    ax = _mm256_fnmadd_ps(f.shearX, az, pickAxis(ax0, ay0, az0, f.kxIs0, f.kxIs1));
    ay = _mm256_fnmadd_ps(f.shearY, az, pickAxis(ax0, ay0, az0, f.kyIs0, f.kyIs1));
    bx = _mm256_fnmadd_ps(f.shearX, bz, pickAxis(bx0, by0, bz0, f.kxIs0, f.kxIs1));
    by = _mm256_fnmadd_ps(f.shearY, bz, pickAxis(bx0, by0, bz0, f.kyIs0, f.kyIs1));
    cx = _mm256_fnmadd_ps(f.shearX, cz, pickAxis(cx0, cy0, cz0, f.kxIs0, f.kxIs1));
    cy = _mm256_fnmadd_ps(f.shearY, cz, pickAxis(cx0, cy0, cz0, f.kyIs0, f.kyIs1));
  }
  const __m256 u = differenceOfProducts8(cx, by, cy, bx);
  const __m256 v = differenceOfProducts8(ax, cy, ay, cx);
  const __m256 w = differenceOfProducts8(bx, ay, by, ax);
  return keepSameSignLanes(u, v, w, lanes, ax, ay, az, bx, by, bz, cx, cy, cz, out);
}

inline TriangleHit finishLane(const ShearedCorners& c, const PacketFrame& f, int i, float tMin, float tMax) {
  return triangle_detail::finishHit(c.ax[i], c.ay[i], c.az[i], c.bx[i], c.by[i], c.bz[i], c.cx[i], c.cy[i],
                                    c.cz[i], f.shearZ[i], tMin, tMax);
}

// |x| per lane (std::abs).
inline __m256 absolute(__m256 x) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), x); }

// Loads the rays of the lanes `active` into the frame, for the triangle test (origins, shears,
// axes) and the box tests (inverse directions); the other lanes get zeros.
inline void loadPacketRays(const RayPacket& packet, std::uint32_t active, PacketFrame& f) {
  alignas(32) float lane[8][kPacketSize];
  alignas(32) int axes[3][kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) {
    if ((active >> i & 1u) == 0) {
      for (float* row : lane) row[i] = 0.0f;
      axes[0][i] = axes[1][i] = axes[2][i] = 0;
      f.shearZ[i] = 0.0f;
      continue;
    }
    const Ray& ray = packet.ray[i];
    lane[0][i] = ray.origin.x;
    lane[1][i] = ray.origin.y;
    lane[2][i] = ray.origin.z;
    lane[3][i] = ray.invDirection.x;
    lane[4][i] = ray.invDirection.y;
    lane[5][i] = ray.invDirection.z;
    lane[6][i] = ray.shearX;
    lane[7][i] = ray.shearY;
    f.shearZ[i] = ray.shearZ;
    axes[0][i] = ray.kx;
    axes[1][i] = ray.ky;
    axes[2][i] = ray.kz;
  }
  for (int a = 0; a < 3; ++a) {
    f.origin[a] = _mm256_load_ps(lane[a]);
    f.invDirection[a] = _mm256_load_ps(lane[3 + a]);
  }
  f.shearX = _mm256_load_ps(lane[6]);
  f.shearY = _mm256_load_ps(lane[7]);
  auto isAxis = [&](int which, int axis) {
    const __m256i values = _mm256_load_si256(reinterpret_cast<const __m256i*>(axes[which]));
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(values, _mm256_set1_epi32(axis)));
  };
  // Inactive lanes were given axes 0, 0, 0 above: compare the active ones only.
  const int firstLane = std::countr_zero(active | (1u << kPacketSize));
  f.uniformAxes = firstLane < kPacketSize;
  if (f.uniformAxes) {
    f.kx = axes[0][firstLane];
    f.ky = axes[1][firstLane];
    f.kz = axes[2][firstLane];
    for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      f.uniformAxes = f.uniformAxes && axes[0][i] == f.kx && axes[1][i] == f.ky && axes[2][i] == f.kz;
    }
  }
  f.kxIs0 = isAxis(0, 0);
  f.kxIs1 = isAxis(0, 1);
  f.kyIs0 = isAxis(1, 0);
  f.kyIs1 = isAxis(1, 1);
  f.kzIs0 = isAxis(2, 0);
  f.kzIs1 = isAxis(2, 1);
}

// The lanes' bounds as one register (inactive lanes: 0).
inline __m256 loadLaneBounds(const float (&bound)[kPacketSize], std::uint32_t active) {
  alignas(32) float lane[kPacketSize];
  for (int i = 0; i < kPacketSize; ++i) lane[i] = (active >> i & 1u) != 0 ? bound[i] : 0.0f;
  return _mm256_load_ps(lane);
}

// The closest-hit and any-hit bookkeeping of a packet, lane by lane as ClosestHit and AnyHit
// (hit_query.hpp) keep it for one ray; shared by the kd-tree's and the BVH's packet walks.
template <typename Filter>
struct PacketClosestHit {
  const RayPacket& packet;
  const PacketFrame& frame;
  const Filter& keeps;
  Hit best[kPacketSize];
  float upper[kPacketSize];
  alignas(32) float bestT[kPacketSize];

  // Each lane of `active` starts at its tMax, then takes its closest hit among `slivers` (the
  // near-degenerate triangles kept out of a tree and tested for every ray).
  void start(std::uint32_t active, std::span<const PackedTriangle> slivers) {
    for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      best[i] = Hit{packet.tMax[i], Hit{}.face};
      upper[i] = packet.tMax[i];
      for (const PackedTriangle& tri : slivers) {
        takeIfCloser(testTriangle(tri, packet.ray[i], packet.tMin[i], upper[i]), tri.face, packet.ray[i],
                     packet.tMax[i], keeps, best[i], upper[i]);
      }
      bestT[i] = best[i].t;
    }
  }
  // The lanes of `active` that hit, with their hits written to `hits`.
  std::uint32_t answer(std::uint32_t active, std::span<Hit, kPacketSize> hits) const {
    std::uint32_t hitLanes = 0;
    for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
      const int i = std::countr_zero(lanes);
      if (!best[i].valid()) continue;
      hits[i] = best[i];
      hitLanes |= 1u << i;
    }
    return hitLanes;
  }

  std::uint32_t test(const PackedTriangle& tri, std::uint32_t lanes) {
    ShearedCorners corners;
    for (std::uint32_t hit = sameSignLanes(tri, frame, lanes, corners); hit != 0; hit &= hit - 1) {
      const int i = std::countr_zero(hit);
      const TriangleHit h = finishLane(corners, frame, i, packet.tMin[i], upper[i]);
      if (takeIfCloser(h, tri.face, packet.ray[i], packet.tMax[i], keeps, best[i], upper[i]))
        bestT[i] = best[i].t;
    }
    return 0;
  }
  // test's finish on lane i for triangle k of an eight-triangle test (the kd walk's testLeafAlone).
  bool finishAlone(const PackedTriangle& tri, int i, const LeafCorners& c, int k) {
    const TriangleHit h =
        triangle_detail::finishHit(c.ax[k], c.ay[k], c.az[k], c.bx[k], c.by[k], c.bz[k], c.cx[k], c.cy[k],
                                   c.cz[k], frame.shearZ[i], packet.tMin[i], upper[i]);
    if (takeIfCloser(h, tri.face, packet.ray[i], packet.tMax[i], keeps, best[i], upper[i]))
      bestT[i] = best[i].t;
    return false;
  }
  __m256 bound() const { return _mm256_load_ps(bestT); }
  float laneBound(int lane) const { return bestT[lane]; }
};

// The lanes of `active` that one of `slivers` blocks (any-hit's start).
template <typename Filter>
std::uint32_t lanesBlockedBySlivers(const RayPacket& packet, std::uint32_t active,
                                    std::span<const PackedTriangle> slivers, const Filter& keeps) {
  std::uint32_t blocked = 0;
  for (std::uint32_t lanes = slivers.empty() ? 0u : active; lanes != 0; lanes &= lanes - 1) {
    const int i = std::countr_zero(lanes);
    for (const PackedTriangle& tri : slivers) {
      const float t = intersectTriangle(tri, packet.ray[i], packet.tMin[i], packet.tMax[i]);
      if (t >= 0.0f && keeps(packet.ray[i], tri.face, t)) {
        blocked |= 1u << i;
        break;
      }
    }
  }
  return blocked;
}

template <typename Filter>
struct PacketAnyHit {
  const RayPacket& packet;
  const PacketFrame& frame;
  const Filter& keeps;
  alignas(32) float tMax[kPacketSize];

  // The lanes of `active` search up to their tMax; the others are done.
  void start(std::uint32_t active) {
    for (int i = 0; i < kPacketSize; ++i) tMax[i] = (active >> i & 1u) != 0 ? packet.tMax[i] : 0.0f;
  }

  std::uint32_t test(const PackedTriangle& tri, std::uint32_t lanes) const {
    ShearedCorners corners;
    std::uint32_t blocked = 0;
    for (std::uint32_t hit = sameSignLanes(tri, frame, lanes, corners); hit != 0; hit &= hit - 1) {
      const int i = std::countr_zero(hit);
      const float t = finishLane(corners, frame, i, packet.tMin[i], packet.tMax[i]).t;
      if (t >= 0.0f && keeps(packet.ray[i], tri.face, t)) blocked |= 1u << i;
    }
    return blocked;
  }
  bool finishAlone(const PackedTriangle& tri, int i, const LeafCorners& c, int k) const {
    const float t =
        triangle_detail::finishHit(c.ax[k], c.ay[k], c.az[k], c.bx[k], c.by[k], c.bz[k], c.cx[k], c.cy[k],
                                   c.cz[k], frame.shearZ[i], packet.tMin[i], packet.tMax[i])
            .t;
    return t >= 0.0f && keeps(packet.ray[i], tri.face, t);
  }
  __m256 bound() const { return _mm256_load_ps(tMax); }
  float laneBound(int lane) const { return tMax[lane]; }
};

#endif  // LANCER_PACKETS_AVX2

}  // namespace LANCER_ISA_NS
}  // namespace lancer::accel
