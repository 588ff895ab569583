// The scene's lights, environment and shadow catcher in scene space, from the description's.
#include "lancer/scene/scene_lights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include <fmt/format.h>

#include "lancer/image/environment_map.hpp"
#include "lancer/scene/render_limits.hpp"

namespace lancer {
namespace {

constexpr float kPi = 3.14159265358979f;

// Any unit vector across `n`.
Vec3 across(const Vec3& n) {
  const Vec3 helper = std::abs(n.y) < 0.9f ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  return normalize(cross(helper, n));
}

// The light in scene space with what the path tracer samples (docs/lighting.md, units): a sun of
// intensity I gives irradiance pi I on a face turned to it, spread over its disc of solid angle
// 2 pi (1 - cos(angle / 2)); an area light of intensity I is, from afar, a point light of intensity
// I with attenuation 1 / d^2 (the point the Whitted model lights with), so its surface's radiance
// is pi I / area (area: the sphere's cross-section, the rect's or the disk's lit side).
SceneLight sceneLight(const PointLight& light, const SceneGeometry& geometry) {
  SceneLight out{geometry.toSceneSpace(light.position), light.intensity, light.attenuation};
  out.type = light.type;
  const Vec3 centre = geometry.bounds.empty() ? Vec3{0, 0, 0} : geometry.bounds.center();
  const float size = geometry.bounds.empty() ? 1.0f : std::max(length(geometry.bounds.extent()), 1e-6f);
  if (light.type == LightType::Sun) {
    out.direction = normalize(toFloat(light.direction));
    const double halfAngle = 0.5 * light.angleDegrees * 3.14159265358979323846 / 180.0;
    out.cosHalfAngle = static_cast<float>(std::cos(halfAngle));
    const double solidAngle = 2.0 * 3.14159265358979323846 * (1.0 - std::cos(halfAngle));
    out.radiance = light.intensity * static_cast<float>(3.14159265358979323846 / solidAngle);
    out.position = centre + out.direction * (1e4f * size);  // the Whitted model's point
    out.attenuation = {1, 0, 0};
    return out;
  }
  if (light.type == LightType::Point) return out;
  out.attenuation = {0, 0, 1};  // the Whitted model's point: 1 / d^2, as the area light from afar
  Vec3 facing = toFloat(light.direction);
  if (length(facing) == 0.0f) facing = centre - out.position;
  facing = length(facing) > 0.0f ? normalize(facing) : Vec3{0, -1, 0};
  out.direction = facing;
  out.radius = static_cast<float>(light.radius);
  if (light.type == LightType::Sphere) {
    out.area = kPi * out.radius * out.radius;
  } else if (light.type == LightType::Rect) {
    const Vec3 u = across(facing);
    out.axisU = u * static_cast<float>(0.5 * light.width);
    out.axisV = cross(facing, u) * static_cast<float>(0.5 * light.height);
    out.area = static_cast<float>(light.width * light.height);
  } else {
    out.axisU = across(facing);
    out.axisV = cross(facing, out.axisU);
    out.area = kPi * out.radius * out.radius;
  }
  out.radiance = light.intensity * (kPi / out.area);
  return out;
}

// Each value the scene file gives fits a float, but an area or a sun's disc so small that it rounds
// to nothing (a radius of 1e-30), or an intensity near the largest float spread over a small area,
// gives a radiance no float holds: refused here, where the light is made, not as a broken pixel.
void checkRadianceIsFinite(const PointLight& light, const SceneLight& made) {
  if (std::isfinite(made.radiance.x) && std::isfinite(made.radiance.y) && std::isfinite(made.radiance.z))
    return;
  const std::string_view type = kLightTypeNames[static_cast<std::size_t>(light.type)];
  const bool sun = light.type == LightType::Sun;
  const std::string size = sun ? fmt::format("angle {}", light.angleDegrees)
                           : light.type == LightType::Rect
                               ? fmt::format("width {} and height {}", light.width, light.height)
                               : fmt::format("radius {}", light.radius);
  const std::string formula = sun ? "pi intensity / the solid angle of its disc"
                                  : fmt::format("pi intensity / area, area {}", made.area);
  throw InputError(light.where,
                   fmt::format("the {} light of {} and intensity [{}, {}, {}] has a radiance ({}) "
                               "too large for a float: give it a larger {} or a smaller intensity",
                               type, size, light.intensity.x, light.intensity.y, light.intensity.z, formula,
                               sun ? "angle" : "size"));
}

// The radiance strength x colour must stay a float, as the light's does.
void checkEnvironmentStrength(const EnvironmentSettings& settings, std::span<const Vec3> colors) {
  float brightest = 0;
  for (const Vec3& c : colors) brightest = std::max({brightest, c.x, c.y, c.z});
  if (std::isfinite(brightest * settings.strength)) return;
  throw InputError(settings.where,
                   fmt::format("environment.strength {} times the environment's brightest value {} is too "
                               "large for a float: lower the strength",
                               settings.strength, brightest));
}

}  // namespace

SceneEnvironment sceneEnvironment(const EnvironmentSettings& settings, const Vec3& up) {
  SceneEnvironment environment;
  environment.kind = settings.kind;
  environment.color = settings.color;
  environment.zenith = settings.zenith;
  environment.horizon = settings.horizon;
  environment.ground = settings.ground;
  environment.up = normalize(up);
  environment.front = across(environment.up);
  // Reduced in double first: a float of a large angle has lost the turn it stands for.
  environment.rotationRadians =
      static_cast<float>(std::fmod(settings.rotationDegrees, 360.0) * 3.14159265358979323846 / 180.0);
  environment.strength = settings.strength;
  environment.visible = settings.visible;
  if (settings.kind != EnvironmentSettings::Kind::Map) {
    const std::array sky{settings.zenith, settings.horizon, settings.ground};
    checkEnvironmentStrength(settings, settings.kind == EnvironmentSettings::Kind::Uniform
                                           ? std::span<const Vec3>(&settings.color, 1)
                                           : std::span<const Vec3>(sky));
    return environment;
  }
  HdrImage image;
  try {
    image = readEnvironmentMap(settings.map);
  } catch (const InputError& error) {
    throw InputError(settings.where, fmt::format("environment.map: {}", error.message()));
  }
  if (image.width != 2 * image.height)
    throw InputError(
        settings.where,
        fmt::format("environment.map: '{}' is {} x {} pixels; an equirectangular map is twice as "
                    "wide as it is high (e.g. 2048 x 1024)",
                    settings.map, image.width, image.height));
  checkEnvironmentStrength(settings, image.pixels);
  environment.mapWidth = image.width;
  environment.mapHeight = image.height;
  environment.map = std::move(image.pixels);
  return environment;
}

ShadowCatcher shadowCatcherOf(const FloorSettings& floor, const SceneGeometry& geometry) {
  ShadowCatcher catcher;
  catcher.normal = toFloat(floor.normal);
  if (floor.height) {
    catcher.offset = static_cast<float>(*floor.height - dot(geometry.origin, floor.normal));
  } else {  // touch the lowest vertex along the normal, so the part stands on it
    float lowest = std::numeric_limits<float>::infinity();
    for (const Vec3& p : geometry.positions) lowest = std::min(lowest, dot(p, catcher.normal));
    catcher.offset = std::isfinite(lowest) ? lowest : 0.0f;
  }
  return catcher;
}

std::vector<SceneLight> sceneLights(const SceneDescription& description, const SceneGeometry& geometry) {
  std::vector<SceneLight> lights;
  lights.reserve(description.lights.size());
  for (const PointLight& light : description.lights) {
    lights.push_back(sceneLight(light, geometry));
    checkRadianceIsFinite(light, lights.back());
  }
  return lights;
}

}  // namespace lancer
