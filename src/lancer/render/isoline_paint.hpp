// Isolines painted on the surfaces (`isolines = {...}` per mesh): where the node field, interpolated
// over the hit face with its corner weights, is near one of the iso values. The distance to the line
// in pixels is the field's distance to the value over its change per pixel (its gradient on the face,
// seen across the ray, times the pixel's world size), so lines keep their width near and far and on
// oblique faces, and their edges are anti-aliased with one sample per pixel.
#pragma once

#include "lancer/math/ray.hpp"
#include "lancer/render/surface_point.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

// Coverage in [0, 1] of the hit face's isolines at `surface` for `ray`, whose pixel is `pixelSize`
// world units wide there; 0 when its mesh draws none. `color` gets the lines' colour.
float isolineCoverage(const Scene& scene, const Ray& ray, const SurfacePoint& surface, float pixelSize,
                      Vec3& color);

// The field's change per world unit across `unitDirection` (the ray's): the in-plane gradient g of a
// field on a plane with unit normal n, moved along the ray onto the plane and projected
// perpendicular to it. Zero when the ray grazes the plane.
float fieldChangeAcrossRay(const Vec3& gradient, const Vec3& normal, const Vec3& unitDirection);

// The gradient of the linear field with values f[0..2] at the corners p[0..2] of a triangle.
Vec3 triangleGradient(const Vec3 p[3], const float f[3]);

}  // namespace lancer
