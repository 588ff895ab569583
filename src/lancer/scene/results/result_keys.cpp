#include "lancer/scene/results/result_keys.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>

#include "lancer/scene/render_limits.hpp"

namespace lancer {
namespace {

constexpr std::array<std::string_view, 3> kUndeformedStyles = {"none", "edges", "ghost"};
constexpr std::array<std::string_view, 2> kOverChoices = {"orbit", "steps"};
constexpr std::array<std::string_view, 2> kRangeChoices = {"all", "step"};
constexpr std::array<std::string_view, 4> kLabelPositions = {"top-left", "top-right", "bottom-left",
                                                             "bottom-right"};

// The label's length and every width and precision in its fields ("{time:12.3g}"), before fmt formats
// it: "{time:1500000000}" would be a string of 1.5 GB.
void checkLabelSize(const std::string& label, const SourceLocation& where) {
  if (characterCount(label) > kMaxDrawnText)
    throw InputError(where, fmt::format("the label is {} characters long; at most {} are drawn",
                                        characterCount(label), kMaxDrawnText));
  for (std::size_t i = 0; i < label.size(); ++i) {
    if (label[i] != '{') continue;
    if (i + 1 < label.size() && label[i + 1] == '{') {
      ++i;  // "{{", a brace
      continue;
    }
    const std::size_t end = label.find('}', i);
    const std::size_t colon = label.find(':', i);
    if (end == std::string::npos || colon == std::string::npos || colon > end) continue;
    const std::string_view spec = std::string_view(label).substr(colon + 1, end - colon - 1);
    if (spec.find('{') != std::string_view::npos)
      throw InputError(where, fmt::format("the label \"{}\" takes a width or precision from another field; "
                                          "write a number up to {}",
                                          label, kMaxLabelFormatNumber));
    for (std::size_t at = 0; at < spec.size();) {
      std::uint64_t number = 0;
      const std::size_t start = at;
      while (at < spec.size() && spec[at] >= '0' && spec[at] <= '9')
        number =
            std::min<std::uint64_t>(number * 10 + static_cast<std::uint64_t>(spec[at++] - '0'), UINT32_MAX);
      if (at == start) ++at;
      if (number > kMaxLabelFormatNumber)
        throw InputError(where,
                         fmt::format("the label \"{}\" asks for a width or precision of {}; at most {} "
                                     "are allowed",
                                     label, spec.substr(start, at - start), kMaxLabelFormatNumber));
    }
    i = end;
  }
}

}  // namespace

void readWarpKeys(const TomlTableReader& mesh, MeshInstance& instance) {
  if (const toml::node* node = mesh.find("warp")) {
    const auto* table = node->as_table();
    if (!table)
      mesh.fail(*node,
                fmt::format("{} must be a table like {{ field = \"displacement\", factor = 2.0 }}, found {}",
                            mesh.qualified("warp"), describeValue(*node)));
    const TomlTableReader reader(*table, mesh.qualified("warp"), mesh.file(), SceneTable::MeshWarp);
    WarpSettings warp;
    warp.where = reader.location(*node);
    const std::optional<std::string> field = reader.nonEmptyString("field");
    if (!field) reader.failMissing("field", "field = \"displacement\" (a $NodeData view of 3 components)");
    warp.field = *field;
    if (auto factor = reader.number("factor")) warp.factor = *factor;
    instance.warp = warp;
  }
  if (auto style = mesh.choice("undeformed", kUndeformedStyles)) {
    instance.undeformed = static_cast<UndeformedStyle>(*style);
    if (!instance.warp && instance.undeformed != UndeformedStyle::None)
      mesh.fail(
          *mesh.find("undeformed"),
          fmt::format("{} shows the shape before a warp, but this mesh has no warp; add warp = {{ field = "
                      "\"displacement\", factor = 1.0 }}",
                      mesh.qualified("undeformed")));
  }
}

void readAnimationStepKeys(const TomlTableReader& reader, AnimationSettings& animation) {
  if (auto over = reader.choice("over", kOverChoices)) animation.overSteps = *over == 1;
  animation.framesGiven = reader.find("frames") != nullptr;
  animation.degreesGiven = reader.find("degrees") != nullptr;
  if (auto range = reader.choice("range", kRangeChoices)) animation.perStepRange = *range == 1;
  if (auto label = reader.text("label", kMaxDrawnText)) {
    formatStepLabel(*label, 0.0, 0, reader.location(*reader.find("label")));  // names checked at load
    animation.label = *label;
  }
  if (auto position = reader.choice("label_position", kLabelPositions))
    animation.labelPosition = static_cast<LabelPosition>(*position);
}

std::string formatStepLabel(const std::string& label, double time, int step, const SourceLocation& where) {
  checkLabelSize(label, where);
  try {
    return fmt::format(fmt::runtime(label), fmt::arg("time", time), fmt::arg("step", step));
  } catch (const fmt::format_error& error) {
    throw InputError(where, fmt::format("the label \"{}\" cannot be formatted ({}): it may use {{time}} and "
                                        "{{step}}, with a format after a colon as in \"t = {{time:.3g}} s\"; "
                                        "write {{{{ and }}}} for braces",
                                        label, error.what()));
  }
}

}  // namespace lancer
