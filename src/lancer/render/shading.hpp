// The three shading modes in one place, for a point a ray hit: which normal it is shaded with, and
// how one light's response to the lighting model (lighting.hpp) is evaluated there.
//   flat:    the face's own normal;
//   Phong:   the corner normals interpolated at the point, the model evaluated there;
//   Gouraud: the model evaluated at each corner with the corner's normal and view, interpolated;
//   unlit:   no model: the material's diffuse colour or the field's colour as it is (every integrator).
// Shadows are per pixel in every mode: the tracer multiplies the response by what its shadow ray
// lets through.
#pragma once

#include <cstdint>

#include "lancer/math/ray.hpp"
#include "lancer/render/surface_point.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

// Whether `face` shows its colour unlit (shading = "unlit"): no lights, no shadows.
inline bool unlitFace(const Scene& scene, std::uint32_t face) {
  return scene.appearance.faceShading[face] == ShadingMode::Unlit;
}

// The unit normal that `face` is shaded with at the point of corner weights `cornerWeight`, on the
// side the ray arrived on (`geometricNormal` is the face normal turned to that side, `normalSign`
// the turn). A degenerate interpolated normal falls back to the face's.
Vec3 shadingNormal(const Scene& scene, std::uint32_t face, const float cornerWeight[4],
                   const Vec3& geometricNormal, float normalSign);

// The unshadowed response to `light` at `surface` (a cap shades flat), for a viewer along `ray`
// (at infinity along it for a parallel view): `kd` is the material's diffuse colour or a field's;
// `toLight` the unit direction to the light from the point, `distance` how far it is.
Vec3 lightResponse(const Scene& scene, const SurfacePoint& surface, const Material& material, const Vec3& kd,
                   const SceneLight& light, const Ray& ray, bool parallelView, const Vec3& toViewer,
                   const Vec3& toLight, float distance);

}  // namespace lancer
