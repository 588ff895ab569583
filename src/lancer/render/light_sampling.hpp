// Next-event estimation for the path tracer: a direction towards each light from a point, with its
// probability density, and the reverse question (a ray sampled by the material: which light with
// area does it see, and how likely was light sampling to pick that direction), for multiple
// importance sampling (Veach & Guibas 1995, the power heuristic).
//
// Units (docs/lighting.md): radiance L in the scene's RGB; a point light of intensity I gives
// irradiance E = pi I att(d) cos(theta), so a Lambertian face of albedo kd (BRDF kd / pi) sends
// kd I att(d) cos(theta): the Whitted model's diffuse term. A sun gives E = pi I cos(theta) (its
// disc of radiance pi I / Omega); an area light's radiance is pi I / area.
//
// Estimators: a point light is a delta (pdf 0, `weight` = E / cos); the sun, a sphere light (both
// sampled uniformly in the cone they subtend: pdf 1 / solid angle) and a rect or disk (uniformly
// by area: pdf d^2 / (cos_l area) per solid angle) return L / pdf as `weight`.
#pragma once

#include <cstdint>
#include <span>

#include "lancer/math/vec3.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

inline constexpr float kPi = 3.14159265358979323846f;

struct LightSample {
  Vec3 direction;  // unit, from the point towards the light
  Vec3 target;     // the end of the shadow ray (on the light, or far along `direction`)
  Vec3 weight;     // incident radiance over the pdf (for a point light: irradiance over cos)
  float pdf = 0;   // per solid angle; 0 for a point light (a delta: no MIS)
};

// A sample of `light` seen from `point`; false when the light cannot light it (behind a one-sided
// light, inside a sphere light, nothing to give). `sceneSize` sets how far a sun's shadow ray goes.
bool sampleLight(const SceneLight& light, const Vec3& point, float u, float v, float sceneSize,
                 LightSample& sample);

// Where a ray from `origin` along unit `direction`, free of geometry up to `tMax` (infinity: it left
// the scene), meets lights with area; adds their radiance, each weighted by the power heuristic
// against `bsdfPdf` (0: a delta lobe chose the ray, weight 1).
Vec3 lightsAlongRay(std::span<const SceneLight> lights, const Vec3& origin, const Vec3& direction, float tMax,
                    float bsdfPdf);

inline float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// An orthonormal frame around unit `n`: (t, b, n).
inline void frameAround(const Vec3& n, Vec3& t, Vec3& b) {
  // Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// A direction in the cone of unit axis `axis` and cosine half-angle `cosMax`, uniform in solid angle.
inline Vec3 sampleCone(const Vec3& axis, float cosMax, float u, float v) {
  const float cosTheta = 1.0f - u * (1.0f - cosMax);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = 2.0f * kPi * v;
  Vec3 t, b;
  frameAround(axis, t, b);
  return normalize(t * (sinTheta * std::cos(phi)) + b * (sinTheta * std::sin(phi)) + axis * cosTheta);
}

// A point of the unit disk, uniform in area (Shirley & Chiu's concentric map).
inline void concentricDisk(float u, float v, float& x, float& y) {
  const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
  if (a == 0.0f && b == 0.0f) {
    x = y = 0.0f;
    return;
  }
  float r, theta;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    theta = (kPi / 4.0f) * (b / a);
  } else {
    r = b;
    theta = kPi / 2.0f - (kPi / 4.0f) * (a / b);
  }
  x = r * std::cos(theta);
  y = r * std::sin(theta);
}

// Cosine-weighted direction about unit `n` (pdf cos / pi).
inline Vec3 sampleCosine(const Vec3& n, float u, float v) {
  float x, y;
  concentricDisk(u, v, x, y);
  const float z = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y));
  Vec3 t, b;
  frameAround(n, t, b);
  return normalize(t * x + b * y + n * z);
}

}  // namespace lancer
