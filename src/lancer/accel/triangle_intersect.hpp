// Ray/triangle intersection shared by every accelerator, so that they agree to the last bit:
// Woop, Benthin & Wald 2013, "Watertight Ray/Triangle Intersection" (JCGT 2(1)). The triangle is
// moved to the ray's origin and sheared so that the ray runs along +z; the three edge functions are
// then computed from float inputs in double, where the products are exact, so an edge shared by two
// triangles gets exactly opposite values in both (whatever the compiler fuses): a ray through a
// shared edge or vertex hits at least one of its triangles, never slips between them. Edges and
// vertices count as inside (closed triangles).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/math/ray.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer {

// One triangle ready for the test; quads become two (corners 0,1,2 and 0,2,3) with the same face.
// Corners, not edges: a vertex shared by two triangles must be transformed identically in both.
struct PackedTriangle {
  Vec3 v0, v1, v2;
  std::uint32_t face;
};

std::vector<PackedTriangle> packTriangles(std::span<const Vec3> positions, std::span<const MeshFace> faces);

// Returns the ray parameter of the hit in (tMin, tMax), or a negative value when there is none.
// Everything is computed and the tests combined with `&` into one branch at the end: inside a
// kd-tree leaf which test fails first is unpredictable (measured with the earlier test).
inline float intersectTriangle(const PackedTriangle& tri, const Ray& ray, float tMin, float tMax) {
  // Corners relative to the origin as indexable arrays (Vec3's operator[] is a select chain, and the
  // axes here vary per ray).
  const Vec3 da = tri.v0 - ray.origin, db = tri.v1 - ray.origin, dc = tri.v2 - ray.origin;
  const float a[3] = {da.x, da.y, da.z}, b[3] = {db.x, db.y, db.z}, c[3] = {dc.x, dc.y, dc.z};
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const float az = a[kz], bz = b[kz], cz = c[kz];
  // Sheared x and y, rounded to float once (the same value for a vertex in every triangle).
  const auto shear = [](float x, float s, float z) {
    return static_cast<float>(double(x) - double(s) * double(z));
  };
  const float ax = shear(a[kx], ray.shearX, az), ay = shear(a[ky], ray.shearY, az);
  const float bx = shear(b[kx], ray.shearX, bz), by = shear(b[ky], ray.shearY, bz);
  const float cx = shear(c[kx], ray.shearX, cz), cy = shear(c[ky], ray.shearY, cz);
  // Edge functions: products of floats are exact in double, so each is rounded once.
  const double u = double(cx) * double(by) - double(cy) * double(bx);
  const double v = double(ax) * double(cy) - double(ay) * double(cx);
  const double w = double(bx) * double(ay) - double(by) * double(ax);
  const double det = u + v + w;
  // Scaled hit distance; t = scaledT / det.
  const double scaledT = (u * double(az) + v * double(bz) + w * double(cz)) * double(ray.shearZ);
  const double t = scaledT / det;
  const bool sameSign = ((u >= 0.0) & (v >= 0.0) & (w >= 0.0)) | ((u <= 0.0) & (v <= 0.0) & (w <= 0.0));
  const auto tf = static_cast<float>(t);
  const bool inside = sameSign & (det != 0.0) & (tf > tMin) & (tf < tMax);
  return inside ? tf : -1.0f;
}

}  // namespace lancer
