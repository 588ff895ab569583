#include "lancer/render/emissive_faces.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/render/ray_offset.hpp"

namespace lancer {
namespace {

float power(const Vec3& emission) { return (emission.x + emission.y + emission.z) / 3.0f; }

}  // namespace

EmissiveFaces::EmissiveFaces(const Scene& scene) : scene_(&scene) {
  const std::vector<Material>& materials = scene.appearance.materials;
  bool anyEmits = false;
  for (const Material& material : materials) anyEmits = anyEmits || power(material.emission) > 0.0f;
  if (!anyEmits) return;
  const SceneGeometry& geometry = scene.geometry;
  double total = 0;
  std::vector<double> cumulative;
  for (std::uint32_t f = 0; f < geometry.faces.size(); ++f) {
    const Vec3& emission = materials[scene.appearance.faceMaterial[f]].emission;
    if (!(power(emission) > 0.0f)) continue;
    const MeshFace& face = geometry.faces[f];
    // A quad is the two triangles the intersector tests (corners 0, 1, 2 and 0, 2, 3).
    for (int half = 0; half < face.cornerCount() - 2; ++half) {
      const Vec3& a = geometry.positions[face.vertex[0]];
      const Vec3& b = geometry.positions[face.vertex[1 + half]];
      const Vec3& c = geometry.positions[face.vertex[2 + half]];
      const float area = 0.5f * length(cross(b - a, c - a));
      if (!(area > 0.0f)) continue;
      triangles_.push_back(Triangle{a, b - a, c - a, geometry.faceNormals[f], emission});
      total += static_cast<double>(area) * power(emission);
      cumulative.push_back(total);
    }
  }
  if (!(total > 0)) {
    triangles_.clear();
    return;
  }
  cumulative_.resize(cumulative.size());
  for (std::size_t i = 0; i < cumulative.size(); ++i)
    cumulative_[i] = static_cast<float>(cumulative[i] / total);
  cumulative_.back() = 1.0f;
  totalPower_ = static_cast<float>(total);
}

float EmissiveFaces::areaDensity(const Vec3& emission) const { return power(emission) / totalPower_; }

bool EmissiveFaces::sample(const Vec3& point, float u, float v, LightSample& sample) const {
  // The triangle u falls in, then u stretched over it (pbrt-v4's sampling of a discrete distribution).
  const auto cell = std::upper_bound(cumulative_.begin(), cumulative_.end(), u);
  const std::size_t i =
      std::min(static_cast<std::size_t>(cell - cumulative_.begin()), cumulative_.size() - 1);
  const float start = i == 0 ? 0.0f : cumulative_[i - 1];
  const float span = cumulative_[i] - start;
  const float w = span > 0.0f ? std::clamp((u - start) / span, 0.0f, 1.0f) : 0.5f;
  // Uniform on the triangle (Shirley's square-root map).
  const Triangle& triangle = triangles_[i];
  const float root = std::sqrt(w);
  const Vec3 onLight = triangle.a + triangle.ab * (root * (1.0f - v)) + triangle.ac * (root * v);
  const Vec3 toLight = onLight - point;
  const float distance2 = dot(toLight, toLight);
  if (!(distance2 > 0.0f)) return false;
  const float distance = std::sqrt(distance2);
  sample.direction = toLight * (1.0f / distance);
  const float cosLight = dot(sample.direction, triangle.normal);
  if (!(std::abs(cosLight) > 0.0f)) return false;
  // Just off the face on the viewer's side, so that the shadow ray does not meet the face itself.
  sample.target = offsetRayOrigin(onLight, cosLight > 0.0f ? -triangle.normal : triangle.normal);
  sample.pdf = areaDensity(triangle.emission) * distance2 / std::abs(cosLight);
  sample.weight = triangle.emission * (1.0f / sample.pdf);
  return true;
}

float EmissiveFaces::pdf(std::uint32_t face, float distance, float cosLight) const {
  if (triangles_.empty() || !(cosLight > 0.0f)) return 0.0f;
  const Vec3& emission = scene_->appearance.materials[scene_->appearance.faceMaterial[face]].emission;
  return areaDensity(emission) * distance * distance / cosLight;
}

}  // namespace lancer
