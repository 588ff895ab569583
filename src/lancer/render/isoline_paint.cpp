#include "lancer/render/isoline_paint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/render/edge_overlay.hpp"

namespace lancer {

Vec3 triangleGradient(const Vec3 p[3], const float f[3]) {
  // g . e1 = f1 - f0 and g . e2 = f2 - f0 with g in the plane: g = ((f1 - f0) e2 x n + (f2 - f0) n x e1) /
  // |n|^2.
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Vec3 n = cross(e1, e2);
  const float area2 = dot(n, n);
  if (!(area2 > 0.0f)) return {0, 0, 0};
  return (cross(e2, n) * (f[1] - f[0]) + cross(n, e1) * (f[2] - f[0])) * (1.0f / area2);
}

float fieldChangeAcrossRay(const Vec3& gradient, const Vec3& normal, const Vec3& unitDirection) {
  // A step w across the ray lands on the plane at w - d (n . w) / (n . d); the field changes by
  // w . (g - n (g . d) / (n . d)). The largest change over unit w perpendicular to d is the length of
  // that vector's part perpendicular to d.
  const float nd = dot(normal, unitDirection);
  if (std::abs(nd) < 1e-6f) return 0.0f;
  const Vec3 h = gradient - normal * (dot(gradient, unitDirection) / nd);
  return length(h - unitDirection * dot(h, unitDirection));
}

float isolineCoverage(const Scene& scene, const Ray& ray, const SurfacePoint& surface, float pixelSize,
                      Vec3& color) {
  if (!scene.isolines || surface.isCap) return 0.0f;
  const IsolineOverlay& overlay = *scene.isolines;
  const std::uint16_t styleIndex = overlay.faceStyle[surface.face];
  if (styleIndex == 0) return 0.0f;
  const IsolineStyle& style = overlay.styles[styleIndex];
  const MeshFace& face = scene.geometry.faces[surface.face];
  const int corners = face.cornerCount();
  // Element-node data: the face's own values, else the values at its vertices.
  const float* cornerValue = overlay.cornerValue.empty()
                                 ? nullptr
                                 : overlay.cornerValue.data() + std::size_t{surface.face} * kCornerSlots;
  if (cornerValue && std::isnan(cornerValue[0])) cornerValue = nullptr;
  Vec3 p[4];
  float f[4];
  float value = 0;
  for (int c = 0; c < corners; ++c) {
    p[c] = scene.geometry.positions[face.vertex[c]];
    f[c] = cornerValue ? cornerValue[c] : overlay.vertexValue[face.vertex[c]];
    value += surface.cornerWeight[c] * f[c];
  }
  if (std::isnan(value) || style.values.empty()) return 0.0f;
  // A quad's bilinear field: the mean of its two triangles' gradients (exact for a linear field).
  Vec3 gradient = triangleGradient(p, f);
  if (corners == 4) {
    const Vec3 q[3] = {p[0], p[2], p[3]};
    const float g[3] = {f[0], f[2], f[3]};
    gradient = (gradient + triangleGradient(q, g)) * 0.5f;
  }
  const Vec3 unitDirection = normalize(ray.direction);
  const Vec3 normal = normalize(cross(p[1] - p[0], p[2] - p[0]));
  const float perPixel = fieldChangeAcrossRay(gradient, normal, unitDirection) * pixelSize;
  if (!(perPixel > 0.0f)) return 0.0f;  // a flat field (or a grazing view) has no lines here
  // The nearest iso values below and above the point's value.
  const auto above = std::lower_bound(style.values.begin(), style.values.end(), value);
  float nearest = std::numeric_limits<float>::infinity();
  auto line = above;
  if (above != style.values.end()) nearest = *above - value;
  if (above != style.values.begin() && value - *(above - 1) < nearest)
    nearest = value - *(above - 1), line = above - 1;
  const float coverage = lineCoverage(nearest / perPixel, style.widthPixels);
  if (coverage > 0.0f)
    color = style.valueColors.empty()
                ? style.color
                : style.valueColors[static_cast<std::size_t>(line - style.values.begin())];
  return coverage;
}

}  // namespace lancer
