#include "lancer/scene/result_keys.hpp"

#include <fmt/format.h>

#include <array>

namespace lancer {
namespace {

constexpr std::array<std::string_view, 3> kUndeformedStyles = {"none", "edges", "ghost"};
constexpr std::array<std::string_view, 2> kOverChoices = {"orbit", "steps"};
constexpr std::array<std::string_view, 2> kRangeChoices = {"all", "step"};
constexpr std::array<std::string_view, 4> kLabelPositions = {"top-left", "top-right", "bottom-left",
                                                             "bottom-right"};

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
  if (auto label = reader.string("label")) {
    formatStepLabel(*label, 0.0, 0, reader.location(*reader.find("label")));  // names checked at load
    animation.label = *label;
  }
  if (auto position = reader.choice("label_position", kLabelPositions))
    animation.labelPosition = static_cast<LabelPosition>(*position);
}

std::string formatStepLabel(const std::string& label, double time, int step, const SourceLocation& where) {
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
