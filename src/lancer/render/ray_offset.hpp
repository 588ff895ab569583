// Where secondary rays start: the hit point pushed off the surface by more than the rounding error of
// its coordinates, so that neither a 1e-3 part nor survey coordinates show self-shadowing acne.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "lancer/math/vec3.hpp"

namespace lancer {

// Relative rounding error allowed per coordinate of a surface point (SurfacePoint::positionError):
// 2^-16, 256 float epsilons. It covers rebuilding the point from the triangle's corners (a few
// epsilons) and the error of the triangle test seen from the moved origin, which grows with the
// corners' distance to it and with 1 / sin of the angle between the ray and the surface: this margin
// holds down to rays about 1 degree off the surface, where a light's cosine is below 0.02.
inline constexpr float kSurfacePointRelativeError = 1.0f / 65536.0f;

// Bound on the error of each coordinate of ray.at(t) (one product and one sum, rounded): for points
// that are not rebuilt from a triangle's corners, such as a clip plane's cap.
inline Vec3 rayPointError(const Vec3& origin, const Vec3& direction, float t) {
  return (abs(origin) + abs(direction * t) * 2.0f) * (4.0f * 0x1p-24f);
}

// std::nextafter(x, +infinity) without the libm call (three per shadow ray origin): the next float
// up, x itself for NaN and +infinity, the smallest denormal for either zero.
inline float floatAbove(float x) {
  if (!(x < INFINITY)) return x;
  if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(x);
  return std::bit_cast<float>(x > 0.0f ? bits + 1 : bits - 1);
}

// Moves p along `normal` (unit, to the side the new ray leaves from) by the error bound `error` (per
// coordinate) projected on it, then rounds each coordinate away from p so that the rounding of the
// sum cannot undo the move. Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed., 6.8.6.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& error, const Vec3& normal) {
  const float distance = dot(abs(normal), error);
  const Vec3 offset = normal * distance;
  auto away = [](float moved, float by) {
    return by > 0.0f ? floatAbove(moved) : (by < 0.0f ? -floatAbove(-moved) : moved);
  };
  const Vec3 moved = p + offset;
  return {away(moved.x, offset.x), away(moved.y, offset.y), away(moved.z, offset.z)};
}

// Wachter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6:
// an offset that scales with each coordinate's own magnitude, for points whose error does (points
// of a shadow ray's crossings, the shadow-catcher floor). A hit point seen from afar is not such a
// point (its error follows the camera's distance and its largest coordinate): see the overload above.
// `normal` must point to the side the new ray leaves from (towards the light, the reflection, ...).
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& normal) {
  constexpr float kOrigin = 1.0f / 32.0f;  // below this magnitude, offset in absolute terms
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;  // offset in units in the last place elsewhere
  auto offsetComponent = [&](float position, float n) {
    const auto ulps = static_cast<std::int32_t>(kIntScale * n);
    const float byUlps =
        std::bit_cast<float>(std::bit_cast<std::int32_t>(position) + (position < 0 ? -ulps : ulps));
    return std::abs(position) < kOrigin ? position + kFloatScale * n : byUlps;
  };
  return {offsetComponent(p.x, normal.x), offsetComponent(p.y, normal.y), offsetComponent(p.z, normal.z)};
}

}  // namespace lancer
