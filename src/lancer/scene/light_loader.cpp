#include "lancer/scene/light_loader.hpp"

#include <array>

#include <fmt/format.h>

#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/scene_keys.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {
namespace {

// A direction that must not be zero, normalised.
std::optional<Vec3d> readDirection(const TomlTableReader& reader, std::string_view key) {
  const std::optional<Vec3d> direction = reader.vector(key, Triple::Xyz);
  if (!direction) return std::nullopt;
  if (length(*direction) == 0.0)
    reader.fail(*reader.find(key), fmt::format("{} must not be [0, 0, 0]", reader.qualified(key)));
  return normalize(*direction);
}

}  // namespace

PointLight readLight(const std::string& path, const toml::table& table, std::size_t index) {
  const TomlTableReader reader(table, fmt::format("light[{}]", index), path, SceneTable::Light);
  PointLight light;
  light.where = reader.location(table);
  if (auto type = reader.choice("type", kLightTypeNames)) light.type = static_cast<LightType>(*type);
  const std::string kind(kLightTypeNames[static_cast<std::size_t>(light.type)]);
  const std::optional<Vec3d> position = reader.vector("position", Triple::Xyz);
  if (light.type == LightType::Sun) {
    const std::optional<Vec3d> direction = readDirection(reader, "direction");
    if (!direction) reader.failMissing("direction", "direction = [x, y, z] (from the scene towards the sun)");
    light.direction = *direction;
    if (auto angle = reader.number("angle", NumberRange::strictlyBetween(0, 180)))
      light.angleDegrees = *angle;
  } else {
    if (!position) reader.failMissing("position", "position = [x, y, z]");
    light.position = *position;
    // rect and disk face `direction`; without it, the scene's centre (resolved when the scene is built).
    if (auto direction = readDirection(reader, "direction"))
      light.direction = *direction;
    else
      light.direction = {0, 0, 0};
  }
  // Keys that belong to other types are mistakes, not silently ignored.
  auto only = [&](std::string_view key, bool allowed, std::string_view which) {
    if (const toml::node* node = reader.find(key); node && !allowed)
      reader.fail(*node, fmt::format("{} is for {} lights; this light has type = \"{}\"",
                                     reader.qualified(key), which, kind));
  };
  only("position", light.type != LightType::Sun, "point and area");
  only("angle", light.type == LightType::Sun, "sun");
  only("radius", light.type == LightType::Sphere || light.type == LightType::Disk, "sphere and disk");
  only("width", light.type == LightType::Rect, "rect");
  only("height", light.type == LightType::Rect, "rect");
  only("attenuation", light.type == LightType::Point, "point");
  if (light.type == LightType::Sphere || light.type == LightType::Disk) {
    const std::optional<double> radius = reader.number("radius", NumberRange::above(0));
    if (!radius) reader.failMissing("radius", "radius = 0.5 (in scene units)");
    light.radius = *radius;
  }
  if (light.type == LightType::Rect) {
    const std::optional<double> width = reader.number("width", NumberRange::above(0));
    const std::optional<double> height = reader.number("height", NumberRange::above(0));
    if (!width) reader.failMissing("width", "width = 1.0 (in scene units)");
    if (!height) reader.failMissing("height", "height = 1.0 (in scene units)");
    light.width = *width;
    light.height = *height;
  }
  if (auto intensity = reader.vector("intensity", Triple::Rgb, NumberRange::atLeast(0)))
    light.intensity = toFloat(*intensity);
  if (auto attenuation = reader.vector("attenuation", Triple::Xyz, NumberRange::atLeast(0))) {
    if (*attenuation == Vec3d{0, 0, 0})
      reader.fail(
          *reader.find("attenuation"),
          fmt::format("{} must not be [0, 0, 0]: att(d) = 1 / (c + l d + q d^2) would divide by zero; "
                      "use [1, 0, 0] for no attenuation",
                      reader.qualified("attenuation")));
    light.attenuation = toFloat(*attenuation);
  }
  return light;
}

EnvironmentSettings readEnvironment(const std::string& path, const std::filesystem::path& folder,
                                    const toml::table& table) {
  const TomlTableReader reader(table, "environment", path, SceneTable::Environment);
  EnvironmentSettings environment;
  environment.where = reader.location(table);
  const NumberRange radiance = NumberRange::atLeast(0);
  const bool gradient = reader.find("zenith") || reader.find("horizon") || reader.find("ground");
  const toml::node* map = reader.find("map");
  const toml::node* color = reader.find("color");
  if ((gradient ? 1 : 0) + (map ? 1 : 0) + (color ? 1 : 0) > 1)
    reader.fail(*(map ? map : color),
                "environment: give one of color (uniform), zenith/horizon/ground (a sky) or map (an image)");
  if (auto value = reader.vector("color", Triple::Rgb, radiance)) environment.color = toFloat(*value);
  if (gradient) {
    environment.kind = EnvironmentSettings::Kind::Gradient;
    if (auto value = reader.vector("zenith", Triple::Rgb, radiance)) environment.zenith = toFloat(*value);
    if (auto value = reader.vector("horizon", Triple::Rgb, radiance)) environment.horizon = toFloat(*value);
    if (auto value = reader.vector("ground", Triple::Rgb, radiance)) environment.ground = toFloat(*value);
  }
  if (auto file = reader.nonEmptyString("map")) {
    environment.kind = EnvironmentSettings::Kind::Map;
    const std::filesystem::path value(*file);
    environment.map = value.is_absolute() ? *file : (folder / value).lexically_normal().string();
    if (map != nullptr) environment.where = reader.location(*map);
  }
  if (auto rotation = reader.number("rotation")) environment.rotationDegrees = *rotation;
  if (auto strength = reader.number("strength", radiance))
    environment.strength = static_cast<float>(*strength);
  if (auto visible = reader.boolean("visible")) environment.visible = *visible;
  return environment;
}

}  // namespace lancer
