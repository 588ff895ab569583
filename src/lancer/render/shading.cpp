#include "lancer/render/shading.hpp"

#include "lancer/render/lighting.hpp"

namespace lancer {

Vec3 shadingNormal(const Scene& scene, std::uint32_t face, const float cornerWeight[4],
                   const Vec3& geometricNormal, float normalSign) {
  const ShadingMode mode = scene.appearance.faceShading[face];
  if (mode == ShadingMode::Flat || mode == ShadingMode::Unlit) return geometricNormal;
  Vec3 n{0, 0, 0};
  const auto& corners = scene.geometry.cornerNormals.faceCorner[face];
  for (int c = 0; c < scene.geometry.faces[face].cornerCount(); ++c)
    n += scene.geometry.cornerNormals.normals[corners[c]] * cornerWeight[c];
  n = normalize(n) * normalSign;
  return dot(n, n) > 0.5f ? n : geometricNormal;
}

Vec3 lightResponse(const Scene& scene, const SurfacePoint& surface, const Material& material, const Vec3& kd,
                   const SceneLight& light, const Ray& ray, bool parallelView, const Vec3& toViewer,
                   const Vec3& toLight, float distance) {
  if (surface.isCap || scene.appearance.faceShading[surface.face] != ShadingMode::Gouraud)
    return directLighting(material, kd, light, surface.shadingNormal, toViewer, toLight, distance);
  // Gouraud: the light's response at each corner, with the corner's own normal and view direction,
  // interpolated across the face.
  const MeshFace& face = scene.geometry.faces[surface.face];
  const auto& corners = scene.geometry.cornerNormals.faceCorner[surface.face];
  Vec3 response{0, 0, 0};
  for (int c = 0; c < face.cornerCount(); ++c) {
    const Vec3& corner = scene.geometry.positions[face.vertex[c]];
    const Vec3 cornerNormal = scene.geometry.cornerNormals.normals[corners[c]] * surface.normalSign;
    const Vec3 cornerToViewer = parallelView ? toViewer : normalize(ray.origin - corner);
    const Vec3 cornerToLight = light.position - corner;
    const float cornerDistance = length(cornerToLight);
    response += directLighting(material, kd, light, cornerNormal, cornerToViewer,
                               cornerToLight * (1.0f / cornerDistance), cornerDistance) *
                surface.cornerWeight[c];
  }
  return response;
}

}  // namespace lancer
