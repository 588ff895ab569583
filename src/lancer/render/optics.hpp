// The laws of a smooth interface used by the tracer: mirror reflection, Snell refraction with total
// internal reflection, and the exact dielectric Fresnel reflectance. Plain functions, for tests too.
#pragma once

#include <algorithm>
#include <cmath>

#include "lancer/math/vec3.hpp"

namespace lancer {

inline Vec3 reflect(const Vec3& direction, const Vec3& normal) {
  return direction - normal * (2.0f * dot(direction, normal));
}

// Snell's law n1 sin(t1) = n2 sin(t2) in vector form (Hecht, Optics, 4.4); `direction` and `normal`
// are unit, `normal` faces the incoming side, eta = n1 / n2. False on total internal reflection,
// i.e. when eta sin(t1) > 1.
inline bool refract(const Vec3& direction, const Vec3& normal, float eta, Vec3& transmitted) {
  const float cosIncident = -dot(direction, normal);
  const float k = 1.0f - eta * eta * (1.0f - cosIncident * cosIncident);
  if (k < 0.0f) return false;
  transmitted = normalize(direction * eta + normal * (eta * cosIncident - std::sqrt(k)));
  return true;
}

// Exact unpolarised Fresnel reflectance of a dielectric interface (Born & Wolf, 1.5.3): the mean of
// the s and p reflectances; cosIncident in [0, 1], eta = n1 / n2. 1 past the critical angle.
inline float dielectricFresnel(float cosIncident, float eta) {
  cosIncident = std::clamp(cosIncident, 0.0f, 1.0f);
  const float sin2Transmitted = eta * eta * (1.0f - cosIncident * cosIncident);
  if (sin2Transmitted >= 1.0f) return 1.0f;
  const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
  const float rs = (eta * cosIncident - cosTransmitted) / (eta * cosIncident + cosTransmitted);
  const float rp = (cosIncident - eta * cosTransmitted) / (cosIncident + eta * cosTransmitted);
  return 0.5f * (rs * rs + rp * rp);
}

// How the light a surface sends on divides between mirror reflection and transmission, given the
// material's shares (`reflect`, `transmit`). Through a solid's surface (`refracts`) the ray bends by
// Snell's law with eta = n_from / n_to, about the shading normal, or the geometric one when the
// shading normal would send it back out; total internal reflection gives the whole transmitted share
// to reflection, and with Fresnel the transmitted share is split again by the dielectric
// reflectance. A thin sheet passes light unbent (its Fresnel term takes eta = sheetEta). Only weight
// moves from transmission to reflection: the sum stays the material's.
struct InterfaceSplit {
  Vec3 reflect;
  float transmit;
  Vec3 transmittedDirection;
};

inline InterfaceSplit splitAtInterface(const Vec3& direction, const Vec3& shadingNormal,
                                       const Vec3& geometricNormal, bool refracts, float eta, bool fresnel,
                                       float sheetEta, const Vec3& reflect, float transmit) {
  InterfaceSplit split{reflect, transmit, direction};
  if (transmit <= 0.0f) return split;
  Vec3 normal = shadingNormal;
  bool transmits = true;
  if (refracts) {
    transmits = refract(direction, normal, eta, split.transmittedDirection);
    if (transmits && dot(split.transmittedDirection, geometricNormal) >= 0.0f) {
      normal = geometricNormal;
      transmits = refract(direction, normal, eta, split.transmittedDirection);
    }
  }
  if (!transmits) {
    split.reflect += Vec3{1, 1, 1} * split.transmit;
    split.transmit = 0.0f;
  } else if (fresnel) {
    const float reflectance = dielectricFresnel(-dot(direction, normal), refracts ? eta : sheetEta);
    split.reflect += Vec3{1, 1, 1} * (split.transmit * reflectance);
    split.transmit *= 1.0f - reflectance;
  }
  return split;
}

inline Vec3 beerLambert(const Vec3& absorption, float distance) {
  return {std::exp(-absorption.x * distance), std::exp(-absorption.y * distance),
          std::exp(-absorption.z * distance)};
}

}  // namespace lancer
