#include "lancer/render/field_shading.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/image/color_map.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

bool fieldColorAt(const Scene& scene, const SurfacePoint& surface, bool linearize, Vec3& color) {
  if (!scene.fieldColors || surface.isCap) return false;
  const FieldColors& fields = *scene.fieldColors;
  const std::uint8_t map = fields.faceColorMap[surface.face];
  if (map == 0) return false;
  float t = 0;
  if (map & FieldColors::kPerFace) {
    t = fields.faceFieldT[surface.face];  // element data: constant over the face
  } else if (map & FieldColors::kPerCorner) {
    const float* corner = fields.cornerFieldT.data() + std::size_t{surface.face} * kCornerSlots;
    const int corners = scene.geometry.faces[surface.face].cornerCount();
    for (int c = 0; c < corners; ++c) t += surface.cornerWeight[c] * corner[c];
  } else {
    const MeshFace& face = scene.geometry.faces[surface.face];
    for (int c = 0; c < face.cornerCount(); ++c)
      t += surface.cornerWeight[c] * fields.vertexFieldT[face.vertex[c]];
  }
  if (std::isnan(t)) return false;
  const FieldMap& fieldMap = fields.maps[static_cast<std::size_t>((map & FieldColors::kMapBits) - 1)];
  if (fieldMap.scale == ColorScale::Log) t = fieldMap.position(t);  // the interpolated value, placed
  if (!fields.faceBands.empty() && fields.faceBands[surface.face] > 0) {
    // Discrete bands (gmsh's "discrete" intervals): each band shows the map at its middle.
    const auto bands = static_cast<float>(fields.faceBands[surface.face]);
    t = (std::min(std::floor(t * bands), bands - 1.0f) + 0.5f) / bands;
  }
  color = fieldMap.colors(t);
  if (linearize) color = {linearFromSrgb(color.x), linearFromSrgb(color.y), linearFromSrgb(color.z)};
  return true;
}

}  // namespace lancer
