// Ray/triangle intersection shared by every accelerator, so that they agree to the last bit.
// Moller & Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection", on pre-gathered
// vertex and edge vectors; edges and vertices count as inside (closed triangles: no cracks).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/math/ray.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

// One triangle ready for the test; quads become two (corners 0,1,2 and 0,2,3) with the same face.
struct PackedTriangle {
  Vec3 v0;
  Vec3 edge1;  // v1 - v0
  Vec3 edge2;  // v2 - v0
  std::uint32_t face;
};

std::vector<PackedTriangle> packTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces);

// Returns the ray parameter of the hit in (tMin, tMax), or a negative value when there is none.
// The barycentric tests compare against the determinant instead of dividing by it (the same
// closed-triangle test in exact arithmetic). Everything is computed and the tests combined with
// `&` into one branch at the end: inside a kd-tree leaf which test fails first is unpredictable,
// and the mispredictions cost more than the few extra multiplies (measured on the bench meshes).
inline float intersectTriangle(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax) {
  const Vec3 p = cross(ray.direction, tri.edge2);
  const float det = dot(tri.edge1, p);
  // u * det and v * det; flip signs for a negative determinant so that 0 <= u, v, u + v <= 1.
  const float sign = det < 0.0f ? -1.0f : 1.0f;
  const float absDet = det * sign;
  const Vec3 s = ray.origin - tri.v0;
  const float uDet = dot(s, p) * sign;
  const Vec3 q = cross(s, tri.edge1);
  const float vDet = dot(ray.direction, q) * sign;
  // det == 0: the ray is parallel to the triangle's plane (or the triangle is degenerate); t is
  // then infinite or NaN, but the test fails on det != 0 whatever it is.
  const float t = dot(tri.edge2, q) / det;
  const bool inside = (det != 0.0f) & (uDet >= 0.0f) & (uDet <= absDet) & (vDet >= 0.0f) &
                      (uDet + vDet <= absDet) & (t > tMin) & (t < tMax);
  return inside ? t : -1.0f;
}

}  // namespace lancer
