// Ray/triangle intersection shared by every accelerator, so that they agree to the last bit:
// Woop, Benthin & Wald 2013, "Watertight Ray/Triangle Intersection" (JCGT 2(1)). The triangle is
// moved to the ray's origin and sheared so that the ray runs along +z, each corner rounded once (the
// same value in every triangle that shares it); the three edge functions are then computed so that
// their signs are exact: an edge shared by two triangles gets opposite signs in both, whatever the
// compiler fuses, so a ray through a shared edge or vertex hits at least one of its triangles, never
// slips between them. Edges and vertices count as inside (closed triangles).
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "lancer/math/ray.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/util/isa.hpp"

namespace lancer {

// One triangle ready for the test; quads become two (corners 0,1,2 and 0,2,3) with the same face.
// Corners, not edges: a vertex shared by two triangles must be transformed identically in both.
struct PackedTriangle {
  Vec3 v0, v1, v2;
  std::uint32_t face;
};

std::vector<PackedTriangle> packTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces);

// Whether the corners are collinear to within a sine of 1e-4 of the corner angle: the determinant (the
// sum of the edge functions) is then rounding noise, so a computed hit may lie anywhere on the ray, far
// outside any box around the triangle. The accelerators test such slivers for every ray, outside their
// trees, so that their answers still equal brute force.
bool isSliverTriangle(const Vec3& a, const Vec3& b, const Vec3& c);

// A hit of one triangle: the ray parameter (negative when there is none) and the barycentric
// weights of corners v1 and v2 (v0's is 1 - b1 - b2), as the test computes them anyway.
struct TriangleHit {
  float t;
  float b1, b2;
};

// Compiled differently in each copy of the kernels (util/isa.hpp): each has its own, so that the
// linker never gives one copy's code to the other.
inline namespace LANCER_ISA_NS {

namespace triangle_detail {

// std::fma on every CPU: one instruction where there is FMA (the x86-64-v3 copy of the kernels,
// ARM64), glibc's correctly rounded fmaf otherwise (the baseline copy, NaiveAccel). So every copy
// and the brute-force reference compute the same bits, and pictures do not depend on the CPU.
// x - s z rounded once: the FMA computes it exactly before rounding.
inline float shear(float x, float s, float z) { return std::fma(-s, z, x); }
// a b - c d within 2 ulps of the exact value (Kahan's algorithm; Jeannerod, Louvet & Muller 2013,
// "Further analysis of Kahan's algorithm for the accurate computation of 2x2 determinants"), so its
// sign is the exact one and it is zero only when the exact value is (or the products underflow).
inline float differenceOfProducts(float a, float b, float c, float d) {
  const float cd = c * d;
  const float cdError = std::fma(-c, d, cd);
  return std::fma(a, b, -cd) + cdError;
}

// The hit of a triangle whose edge functions' signs agree, from its sheared corners relative to
// the ray's origin; one function for the single-ray and the packet tests (kd/packet_traversal.cpp),
// so that both give the same bits. The distance from the edge functions in double, where the products of
// floats are exact: each is rounded once, so two triangles that share the edge a ray passes through compute
// the same t to the last float bit, and the tie goes to the lower face as in the brute-force loop.
inline TriangleHit finishHit(float ax, float ay, float az, float bx, float by, float bz, float cx, float cy,
                             float cz, float shearZ, float tMin, float tMax) {
  const double ud = double(cx) * double(by) - double(cy) * double(bx);
  const double vd = double(ax) * double(cy) - double(ay) * double(cx);
  const double wd = double(bx) * double(ay) - double(by) * double(ax);
  const double det = ud + vd + wd;
  const double scaledT = (ud * double(az) + vd * double(bz) + wd * double(cz)) * double(shearZ);
  const auto t = static_cast<float>(scaledT / det);
  const double invDet = 1.0 / det;
  const bool inside = (det != 0.0) & (t > tMin) & (t < tMax);
  return {inside ? t : -1.0f, static_cast<float>(vd * invDet), static_cast<float>(wd * invDet)};
}

}  // namespace triangle_detail

// The hit with t in (tMin, tMax), or t < 0 when there is none. The edge functions' signs are found
// in float (pbrt-v4, section 6.5.3): most tests end there, the ray's line missing the triangle. Only
// for the few that pass are the edge functions and t recomputed in double (measured: 9% more rays
// per second than finishing in float with one branch at the end, and t stays what the all-double
// test gave, see below).
inline TriangleHit testTriangle(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax) {
  using triangle_detail::differenceOfProducts;
  using triangle_detail::shear;
  // Corners relative to the origin as indexable arrays (Vec3's operator[] is a select chain, and the
  // axes here vary per ray).
  const Vec3 da = tri.v0 - ray.origin, db = tri.v1 - ray.origin, dc = tri.v2 - ray.origin;
  const float a[3] = {da.x, da.y, da.z}, b[3] = {db.x, db.y, db.z}, c[3] = {dc.x, dc.y, dc.z};
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const float az = a[kz], bz = b[kz], cz = c[kz];
  const float ax = shear(a[kx], ray.shearX, az), ay = shear(a[ky], ray.shearY, az);
  const float bx = shear(b[kx], ray.shearX, bz), by = shear(b[ky], ray.shearY, bz);
  const float cx = shear(c[kx], ray.shearX, cz), cy = shear(c[ky], ray.shearY, cz);
  const float u = differenceOfProducts(cx, by, cy, bx);
  const float v = differenceOfProducts(ax, cy, ay, cx);
  const float w = differenceOfProducts(bx, ay, by, ax);
  // The signs alone decide whether the ray's line meets the triangle: most tests end here.
  const bool sameSign = ((u >= 0.0f) & (v >= 0.0f) & (w >= 0.0f)) | ((u <= 0.0f) & (v <= 0.0f) & (w <= 0.0f));
  if (!sameSign) return {-1.0f, 0.0f, 0.0f};
  return triangle_detail::finishHit(ax, ay, az, bx, by, bz, cx, cy, cz, ray.shearZ, tMin, tMax);
}

// The ray parameter of the hit alone (any-hit queries and tests).
inline float intersectTriangle(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax) {
  return testTriangle(tri, ray, tMin, tMax).t;
}

}  // namespace LANCER_ISA_NS

}  // namespace lancer
