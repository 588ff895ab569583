#include "lancer/render/light_sampling.hpp"

#include <cmath>
#include <limits>

#include "lancer/render/lighting.hpp"

namespace lancer {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The cone a sphere light subtends from `point`: false from inside it.
bool sphereCone(const SceneLight& light, const Vec3& point, Vec3& axis, float& distance, float& cosMax) {
  const Vec3 toCentre = light.position - point;
  distance = length(toCentre);
  if (!(distance > light.radius)) return false;
  axis = toCentre * (1.0f / distance);
  const float sin2 = (light.radius * light.radius) / (distance * distance);
  cosMax = std::sqrt(std::max(0.0f, 1.0f - sin2));
  return cosMax < 1.0f;
}

float conePdf(float cosMax) { return 1.0f / (2.0f * kPi * (1.0f - cosMax)); }

// The nearer crossing of the ray with a sphere, or infinity.
float hitSphere(const Vec3& centre, float radius, const Vec3& origin, const Vec3& direction) {
  const Vec3 oc = origin - centre;
  const float b = dot(oc, direction);
  const float c = dot(oc, oc) - radius * radius;
  const float discriminant = b * b - c;
  if (discriminant < 0.0f) return kInfinity;
  const float root = std::sqrt(discriminant);
  const float t = -b - root;
  return t > 0.0f ? t : kInfinity;
}

// Rect or disk: the ray's crossing with the lit side, its point's offset in the plane.
bool hitFlatLight(const SceneLight& light, const Vec3& origin, const Vec3& direction, float& t) {
  const float rate = dot(direction, light.direction);
  if (!(rate < 0.0f)) return false;  // only the lit side shines
  t = dot(light.position - origin, light.direction) / rate;
  if (!(t > 0.0f)) return false;
  const Vec3 offset = origin + direction * t - light.position;
  if (light.type == LightType::Rect) {
    const float s = dot(offset, light.axisU) / dot(light.axisU, light.axisU);
    const float r = dot(offset, light.axisV) / dot(light.axisV, light.axisV);
    return std::abs(s) <= 1.0f && std::abs(r) <= 1.0f;
  }
  return dot(offset, offset) <= light.radius * light.radius;
}

}  // namespace

bool sampleLight(const SceneLight& light, const Vec3& point, float u, float v, float sceneSize,
                 LightSample& sample) {
  switch (light.type) {
    case LightType::Point: {
      const Vec3 toLight = light.position - point;
      const float distance = length(toLight);
      if (!(distance > 0.0f)) return false;
      sample.direction = toLight * (1.0f / distance);
      sample.target = light.position;
      sample.weight = light.intensity * (kPi * lightAttenuation(light, distance));
      sample.pdf = 0.0f;
      return true;
    }
    case LightType::Sun: {
      sample.direction =
          light.cosHalfAngle < 1.0f ? sampleCone(light.direction, light.cosHalfAngle, u, v) : light.direction;
      sample.target = point + sample.direction * (4.0f * sceneSize + 1.0f);
      sample.pdf = light.cosHalfAngle < 1.0f ? conePdf(light.cosHalfAngle) : 0.0f;
      sample.weight =
          light.cosHalfAngle < 1.0f ? light.radiance * (1.0f / sample.pdf) : light.intensity * kPi;
      return true;
    }
    case LightType::Sphere: {
      Vec3 axis;
      float distance, cosMax;
      if (!sphereCone(light, point, axis, distance, cosMax)) return false;
      sample.direction = sampleCone(axis, cosMax, u, v);
      const float t = hitSphere(light.position, light.radius, point, sample.direction);
      // A direction at the cone's very rim may miss in float: end it at the tangent distance.
      const float reach = std::isfinite(t) ? t : distance * cosMax;
      sample.target = point + sample.direction * reach;
      sample.pdf = conePdf(cosMax);
      sample.weight = light.radiance * (1.0f / sample.pdf);
      return true;
    }
    case LightType::Rect:
    case LightType::Disk: {
      Vec3 onLight;
      if (light.type == LightType::Rect) {
        onLight = light.position + light.axisU * (2.0f * u - 1.0f) + light.axisV * (2.0f * v - 1.0f);
      } else {
        float x, y;
        concentricDisk(u, v, x, y);
        onLight = light.position + (light.axisU * x + light.axisV * y) * light.radius;
      }
      const Vec3 toLight = onLight - point;
      const float distance2 = dot(toLight, toLight);
      if (!(distance2 > 0.0f)) return false;
      const float distance = std::sqrt(distance2);
      sample.direction = toLight * (1.0f / distance);
      const float cosLight = -dot(sample.direction, light.direction);
      if (!(cosLight > 0.0f)) return false;
      sample.target = onLight;
      sample.pdf = distance2 / (cosLight * light.area);
      sample.weight = light.radiance * (1.0f / sample.pdf);
      return true;
    }
  }
  return false;
}

Vec3 lightsAlongRay(std::span<const SceneLight> lights, const Vec3& origin, const Vec3& direction, float tMax,
                    float bsdfPdf) {
  Vec3 radiance{0, 0, 0};
  for (const SceneLight& light : lights) {
    float lightPdf = 0.0f;
    switch (light.type) {
      case LightType::Point:
        continue;
      case LightType::Sun:
        if (std::isfinite(tMax) || light.cosHalfAngle >= 1.0f ||
            dot(direction, light.direction) < light.cosHalfAngle)
          continue;
        lightPdf = conePdf(light.cosHalfAngle);
        break;
      case LightType::Sphere: {
        Vec3 axis;
        float distance, cosMax;
        if (!sphereCone(light, origin, axis, distance, cosMax)) continue;
        if (!(hitSphere(light.position, light.radius, origin, direction) < tMax)) continue;
        lightPdf = conePdf(cosMax);
        break;
      }
      case LightType::Rect:
      case LightType::Disk: {
        float t;
        if (!hitFlatLight(light, origin, direction, t) || !(t < tMax)) continue;
        lightPdf = t * t / (-dot(direction, light.direction) * light.area);
        break;
      }
    }
    radiance += light.radiance * (bsdfPdf > 0.0f ? powerHeuristic(bsdfPdf, lightPdf) : 1.0f);
  }
  return radiance;
}

}  // namespace lancer
