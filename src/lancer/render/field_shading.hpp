// The colour a field-coloured face (color_by) shows at a hit: the field's normalised value t,
// interpolated with the face's corner weights (scalars are interpolated, then mapped, as gmsh
// does), looked up in the face's colour map. The tracer uses it as the surface's ka and kd.
#pragma once

#include "lancer/math/vec3.hpp"
#include "lancer/render/surface_point.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

// False when the face is not coloured (or the file gives no value there): use the material.
// `linearize`: the output is sRGB-encoded, so the map's display values are decoded to linear
// first, and the picture shows the map's published colours with either encoding.
bool fieldColorAt(const Scene& scene, const SurfacePoint& surface, bool linearize, Vec3& color);

}  // namespace lancer
