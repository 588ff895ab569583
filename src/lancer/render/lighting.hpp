// The empirical lighting model lancer renders with (Phong's, with the mirror vector R), per RGB
// channel, for one point light:
//   Is * att(d) * (kd * max(0, N.L) + ks * max(0, R.V)^n),   R = L mirrored about N,
// with the specular term 0 when the light is behind the surface (N.L <= 0).
#pragma once

#include <cmath>

#include "lancer/math/vec3.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

inline float lightAttenuation(const SceneLight& light, float distance) {
  // No fall-off (the default): the division below gives 1 exactly (or 1 for its NaN when d d
  // overflows), at the cost of a divide per light and point.
  if (light.attenuation.x == 1.0f && light.attenuation.y == 0.0f && light.attenuation.z == 0.0f) return 1.0f;
  const float denominator =
      light.attenuation.x + light.attenuation.y * distance + light.attenuation.z * distance * distance;
  return denominator > 0.0f ? 1.0f / denominator : 1.0f;
}

// x^n for x in (0, 1]: by repeated squaring when n is a whole number up to 1024 (every shininess in
// the examples; powf costs 5% of examples/demo.toml), std::pow otherwise. The product of at most
// 2 log2(n) roundings is within n float ulps of x^n (relative 6e-5 at n = 1024), far below the
// 1/255 step of an 8-bit pixel.
inline float specularPower(float x, float n) {
  const int whole = static_cast<int>(n);
  if (!(static_cast<float>(whole) == n && whole >= 0 && whole <= 1024)) return std::pow(x, n);
  float result = 1.0f, square = x;
  for (unsigned e = static_cast<unsigned>(whole); e != 0; e >>= 1) {
    result *= (e & 1u) != 0 ? square : 1.0f;  // times 1 is exact: branch-free, same value
    square *= square;
  }
  return result;
}

// `normal` and `toViewer` are unit vectors; `toLight` is unit, `lightDistance` the distance to the light.
// `kd`: the diffuse colour to use, the material's or a field colour map's (color_by).
inline Vec3 directLighting(const Material& material, const Vec3& kd, const SceneLight& light,
                           const Vec3& normal, const Vec3& toViewer, const Vec3& toLight,
                           float lightDistance) {
  const float cosTheta = dot(normal, toLight);
  if (cosTheta <= 0.0f) return {0, 0, 0};
  const Vec3 reflected = normal * (2.0f * cosTheta) - toLight;
  const float cosAlpha = dot(reflected, toViewer);
  const float specular = cosAlpha > 0.0f ? specularPower(cosAlpha, material.shininess) : 0.0f;
  const Vec3 response = kd * cosTheta + material.ks * specular;
  return light.intensity * response * lightAttenuation(light, lightDistance);
}

inline Vec3 directLighting(const Material& material, const SceneLight& light, const Vec3& normal,
                           const Vec3& toViewer, const Vec3& toLight, float lightDistance) {
  return directLighting(material, material.kd, light, normal, toViewer, toLight, lightDistance);
}

}  // namespace lancer
