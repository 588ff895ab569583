// The shading data of the closest hit, built once per hit: position, normals turned towards the
// viewer, and the interpolation weights of the face's corners (barycentric or bilinear).
#pragma once

#include <cstdint>

#include "lancer/accel/hit.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

struct SurfacePoint {
  // On the hit triangle, rebuilt from its corners: ray.at(t) is off the surface by the rounding of
  // the ray's origin and length (a camera 7,500 units away puts it 1e-4 off), which no offset
  // proportional to the point's own coordinates covers where they are small.
  Vec3 position;
  Vec3 positionError;     // bound per coordinate, for offsetRayOrigin (ray_offset.hpp)
  Vec3 geometricNormal;   // unit, on the side the ray came from
  Vec3 shadingNormal;     // unit, interpolated corner normals (flat: the geometric normal)
  float cornerWeight[4];  // weights of the face's corners; 0 for the missing fourth of a triangle
  float normalSign;       // +1 when the ray hit the side the file's winding faces, else -1
  std::uint32_t face;
  bool isCap = false;  // the flat cut face of a clip plane, not a point of `face` itself
};

// Weights of the corners of `face` at point p on it: barycentric for a triangle, inverse-bilinear
// (u, v) for a quad, so quads interpolate bilinearly as the element's own shape functions do.
void faceCornerWeights(const Scene& scene, const MeshFace& face, const Vec3& p, float weights[4]);

SurfacePoint makeSurfacePoint(const Scene& scene, const Ray& ray, const Hit& hit);

// The flat cut face of a capped clip plane where `ray` meets it at `t`, inside the shell of `face`
// (the face the ray leaves by). The ray came from the removed side, where the plane's normal points,
// so the cap faces it; the corner weights are equal, so a field-coloured shell colours its cap with
// the mean of that face. Both integrators shade caps from this one point.
SurfacePoint makeCapPoint(const Scene& scene, const Ray& ray, const ClipPlane& plane, float t,
                          std::uint32_t face);

}  // namespace lancer
