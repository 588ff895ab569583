#include "lancer/scene/animation_keys.hpp"

#include <fmt/format.h>

#include <charconv>
#include <optional>
#include <string_view>

#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {
namespace {

// K of "light:K", K written in decimal digits only.
std::optional<int> orbitLightIndex(std::string_view text) {
  constexpr std::string_view kPrefix = "light:";
  if (!text.starts_with(kPrefix)) return std::nullopt;
  const std::string_view digits = text.substr(kPrefix.size());
  const char* last = digits.data() + digits.size();
  int index = 0;
  const auto [end, error] = std::from_chars(digits.data(), last, index);
  if (digits.empty() || digits.front() == '-' || error != std::errc() || end != last) return std::nullopt;
  return index;
}

// "camera" -> -1, "light:K" -> K, checked against the number of [[light]] tables.
int readOrbit(const TomlTableReader& reader, std::size_t lightCount) {
  const toml::node* node = reader.find("orbit");
  const std::string text = *reader.string("orbit");
  if (text == "camera") return -1;
  const std::optional<int> index = orbitLightIndex(text);
  if (!index)
    reader.fail(*node,
                fmt::format("animation.orbit must be \"camera\" or \"light:K\" (K the index of a [[light]], "
                            "from 0), found \"{}\"",
                            text));
  if (static_cast<std::size_t>(*index) >= lightCount)
    reader.fail(*node, fmt::format("animation.orbit names light {}, but the scene has {}", *index,
                                   lightCount == 0   ? std::string("no [[light]]")
                                   : lightCount == 1 ? std::string("1 light (use \"light:0\")")
                                                     : fmt::format("{} lights (light:0 to light:{})",
                                                                   lightCount, lightCount - 1)));
  return *index;
}

}  // namespace

AnimationSettings readAnimation(const toml::table& table, const std::string& path, std::size_t lightCount) {
  const TomlTableReader reader(table, "animation", path, SceneTable::Animation);
  AnimationSettings animation;
  if (auto frames = reader.integer("frames"))
    animation.frames = checkFrames(*frames, reader.settingName("frames"));
  if (auto fps = reader.number("fps")) animation.fps = checkFps(*fps, reader.settingName("fps"));
  if (reader.find("orbit")) animation.orbitLight = readOrbit(reader, lightCount);
  if (auto axis = reader.vector("axis", Triple::Xyz)) {
    if (length(*axis) == 0)
      reader.fail(*reader.find("axis"),
                  "animation.axis must not be [0, 0, 0]; give the direction to orbit "
                  "about, e.g. [0, 1, 0]");
    animation.axis = *axis;
  }
  animation.center = reader.vector("center", Triple::Xyz);
  if (auto degrees = reader.number("degrees")) animation.degrees = *degrees;
  readAnimationStepKeys(reader, animation);
  return animation;
}

}  // namespace lancer
