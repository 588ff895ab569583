// Where secondary rays start: the hit point pushed off the surface by an amount that scales with the
// magnitude of its coordinates, so that neither a 1e-3 part nor a 1e6 part shows self-shadowing acne.
// Wachter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "lancer/math/vec3.hpp"

namespace lancer {

// `normal` must point to the side the new ray leaves from (towards the light, the reflection, ...).
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& normal) {
  constexpr float kOrigin = 1.0f / 32.0f;       // below this magnitude, offset in absolute terms
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;           // offset in units in the last place elsewhere
  auto offsetComponent = [&](float position, float n) {
    const auto ulps = static_cast<std::int32_t>(kIntScale * n);
    const float byUlps =
        std::bit_cast<float>(std::bit_cast<std::int32_t>(position) + (position < 0 ? -ulps : ulps));
    return std::abs(position) < kOrigin ? position + kFloatScale * n : byUlps;
  };
  return {offsetComponent(p.x, normal.x), offsetComponent(p.y, normal.y), offsetComponent(p.z, normal.z)};
}

}  // namespace lancer
