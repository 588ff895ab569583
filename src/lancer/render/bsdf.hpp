// The path tracer's material at a point, mapped physically from the scene's keys:
//   kd: Lambertian albedo, BRDF kd / pi;
//   ks, shininess n: energy-conserving normalised Phong lobe about the mirror direction,
//     BRDF ks (n + 2) / (2 pi) cos^n(alpha) (Lafortune & Willems, "Using the modified Phong
//     reflectance model for physically based rendering", 1994); kd and ks are scaled down together
//     where kd + ks exceeds 1, so a face never reflects more than it receives;
//   reflectivity: a perfect mirror; transparency, ior, fresnel, absorption: a smooth dielectric
//     (the Whitted model's split, Fresnel and total internal reflection: optics.hpp) with
//     Beer-Lambert absorption inside; these delta lobes take their shares of the light first, the
//     local (kd, ks) lobe what is left (EnergySplit::local).
// Directions are unit and point away from the surface; `normal` is the shading normal on the side
// the path arrived from.
#pragma once

#include <algorithm>
#include <cmath>

#include "lancer/render/light_sampling.hpp"
#include "lancer/render/optics.hpp"

namespace lancer {

struct LocalBsdf {
  Vec3 kd, ks;
  float shininess = 0;
  Vec3 normal;  // shading normal
  Vec3 toViewer;
  float diffuseChance = 1;  // of sampling the diffuse lobe rather than the Phong lobe

  LocalBsdf(const Vec3& diffuse, const Vec3& specular, float n, const Vec3& shadingNormal, const Vec3& wo)
      : kd(diffuse), ks(specular), shininess(n), normal(shadingNormal), toViewer(wo) {
    const float sum = std::max({kd.x + ks.x, kd.y + ks.y, kd.z + ks.z});
    if (sum > 1.0f) {
      kd = kd * (1.0f / sum);
      ks = ks * (1.0f / sum);
    }
    const float d = maxComponent(kd), s = maxComponent(ks);
    diffuseChance = d + s > 0.0f ? d / (d + s) : 1.0f;
  }
  bool black() const { return maxComponent(kd + ks) <= 0.0f; }
  Vec3 mirrorOfViewer() const { return reflect(-toViewer, normal); }
  float phongCosine(const Vec3& wi) const { return std::max(0.0f, dot(mirrorOfViewer(), wi)); }

  Vec3 eval(const Vec3& wi) const {
    if (dot(wi, normal) <= 0.0f) return {0, 0, 0};
    Vec3 f = kd * (1.0f / kPi);
    if (maxComponent(ks) > 0.0f)
      f += ks * ((shininess + 2.0f) / (2.0f * kPi) * std::pow(phongCosine(wi), shininess));
    return f;
  }
  float pdf(const Vec3& wi) const {
    const float cosTheta = dot(wi, normal);
    if (cosTheta <= 0.0f) return 0.0f;
    float p = diffuseChance * cosTheta / kPi;
    if (diffuseChance < 1.0f)
      p += (1.0f - diffuseChance) * (shininess + 1.0f) / (2.0f * kPi) * std::pow(phongCosine(wi), shininess);
    return p;
  }
  // A direction by the lobes' mixture; `choose` picks the lobe.
  Vec3 sample(float choose, float u, float v) const {
    if (choose < diffuseChance) return sampleCosine(normal, u, v);
    const float cosAlpha = std::pow(u, 1.0f / (shininess + 1.0f));
    const float sinAlpha = std::sqrt(std::max(0.0f, 1.0f - cosAlpha * cosAlpha));
    const float phi = 2.0f * kPi * v;
    Vec3 t, b;
    const Vec3 axis = mirrorOfViewer();
    frameAround(axis, t, b);
    return normalize(t * (sinAlpha * std::cos(phi)) + b * (sinAlpha * std::sin(phi)) + axis * cosAlpha);
  }
};

}  // namespace lancer
