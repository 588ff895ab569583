#include "lancer/scene/results/gmsh_post_options.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "lancer/mesh/field_steps.hpp"

namespace lancer {

std::vector<GmshPostView> readGmshPostViews(const std::string& path) {
  std::ifstream in(path);
  if (!in) return {};  // readGmshView has said why already
  std::map<int, GmshPostView> views;
  std::string line;
  for (std::int64_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
    constexpr std::string_view kPrefix = "View[";
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, kPrefix.size(), kPrefix) != 0) continue;
    const std::size_t close = line.find("].", start);
    const std::size_t equals = line.find('=', start);
    if (close == std::string::npos || equals == std::string::npos || equals < close) continue;
    int index = -1;
    const char* digits = line.data() + start + kPrefix.size();
    const auto [end, error] = std::from_chars(digits, line.data() + close, index);
    if (error != std::errc() || end != line.data() + close || index < 0 || index > 100000) continue;
    std::string name = line.substr(close + 2, equals - close - 2);
    name.erase(name.find_last_not_of(" \t") + 1);
    std::string value = line.substr(equals + 1);
    value = value.substr(0, value.find(';'));
    const std::size_t first = value.find_first_not_of(" \t");
    GmshPostView& view = views[index];
    view.index = index;
    if (view.line == 0) view.line = lineNumber;
    if (first == std::string::npos) continue;
    if (name == "Name" && value[first] == '"') {
      const std::size_t last = value.find('"', first + 1);
      view.name = value.substr(first + 1, last == std::string::npos ? std::string::npos : last - first - 1);
      continue;
    }
    constexpr std::array<std::string_view, 13> kNumbers = {
        "TimeStep",      "VectorType", "DisplacementFactor", "RangeType",      "CustomMin",    "CustomMax",
        "IntervalsType", "NbIso",      "ShowScale",          "ColormapNumber", "ColormapSwap", "Visible",
        "ExternalView"};
    const auto known = std::find(kNumbers.begin(), kNumbers.end(), name);
    if (known == kNumbers.end()) {  // colours, fonts, the rest: named, not drawn
      // What gmsh writes of every view and no one sets: the read-only values, the step count, and
      // the time of the step shown (TimeStep says which).
      const bool writtenAlways = line.find("(read-only)") != std::string::npos ||
                                 line.find("(do not change this!)") != std::string::npos || name == "Time";
      if (name != "Name" && !writtenAlways) view.unapplied.push_back(name);
      continue;
    }
    char* numberEnd = nullptr;
    const double number = std::strtod(value.c_str() + first, &numberEnd);
    if (numberEnd == value.c_str() + first || !std::isfinite(number))
      throw InputError(
          SourceLocation{path, lineNumber, static_cast<std::int64_t>(equals + 2)},
          fmt::format("View[{}].{} should be a number, not '{}'", index, name, value.substr(first)));
    // Every key but these three is an integer; a value no int holds is refused, not wrapped.
    const bool real = name == "DisplacementFactor" || name == "CustomMin" || name == "CustomMax";
    const double rounded = std::round(number);
    if (!real && (rounded < std::numeric_limits<int>::min() || rounded > std::numeric_limits<int>::max()))
      throw InputError(
          SourceLocation{path, lineNumber, static_cast<std::int64_t>(equals + first + 2)},
          fmt::format("View[{}].{} = {} is out of range: gmsh keeps it as an integer from {} to {}", index,
                      name, value.substr(first), std::numeric_limits<int>::min(),
                      std::numeric_limits<int>::max()));
    const int whole = real ? 0 : static_cast<int>(rounded);
    switch (known - kNumbers.begin()) {
      case 0:
        view.timeStep = whole;
        break;
      case 1:
        view.vectorType = whole;
        break;
      case 2:
        view.displacementFactor = number;
        break;
      case 3:
        view.rangeType = whole;
        break;
      case 4:
        view.customMin = number;
        break;
      case 5:
        view.customMax = number;
        break;
      case 6:
        view.intervalsType = whole;
        break;
      case 7:
        view.nbIso = whole;
        break;
      case 8:
        view.showScale = whole != 0;
        break;
      case 9:
        if (!ColorMap::named(fmt::format("gmsh:{}", whole)))
          throw InputError(
              SourceLocation{path, lineNumber, static_cast<std::int64_t>(equals + first + 2)},
              fmt::format("View[{}].ColormapNumber = {}: gmsh's colour maps are 0 to 24", index, whole));
        view.colormapNumber = whole;
        break;
      case 10:
        view.colormapSwap = whole != 0;
        break;
      case 11:
        view.visible = whole != 0;
        break;
      default:
        view.externalView = whole;
        break;
    }
  }
  std::vector<GmshPostView> result;
  result.reserve(views.size());
  for (auto& [index, view] : views) result.push_back(std::move(view));
  return result;
}

void applyGmshPostViews(SceneDescription& description, const Mesh& mesh,
                        const std::vector<GmshPostView>& views, const std::string& path) {
  if (views.empty() || description.meshes.empty()) return;
  MeshInstance& instance = description.meshes.front();
  const std::vector<std::string> names = viewNames(mesh);
  const auto nameOf = [&](const GmshPostView& view) -> std::string {
    if (view.name) return *view.name;
    if (view.index >= static_cast<int>(names.size()))
      throw InputError(
          SourceLocation{path, view.line, 1},
          fmt::format("View[{}] is set here, but {} has {} view{} ({}): the options belong to another "
                      "file, or save them again from gmsh with this mesh open",
                      view.index, mesh.source.path, names.size(), names.size() == 1 ? "" : "s",
                      describeViews(mesh)));
    return names[static_cast<std::size_t>(view.index)];
  };
  std::vector<std::string> unapplied;
  for (const GmshPostView& view : views)
    for (const std::string& option : view.unapplied)
      unapplied.push_back(fmt::format("View[{}].{}", view.index, option));
  if (!unapplied.empty())
    description.notes.push_back(fmt::format(
        "{}: warning: lancer does not draw these gmsh options: {}{}", path,
        fmt::join(unapplied.begin(),
                  unapplied.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(unapplied.size(), 8)),
                  ", "),
        unapplied.size() > 8 ? fmt::format(" and {} more", unapplied.size() - 8) : ""));
  const GmshPostView* displacement = nullptr;
  const GmshPostView* colour = nullptr;
  const GmshPostView* arrows = nullptr;
  for (const GmshPostView& view : views) {
    if (!view.visible) continue;
    const std::vector<const MeshField*> steps = viewSteps(mesh, nameOf(view));
    const bool vector =
        !steps.empty() && steps.front()->components == 3 && steps.front()->at != FieldAt::kElement;
    if (view.vectorType == 5 && vector && !displacement)
      displacement = &view;
    else if (view.vectorType >= 1 && view.vectorType <= 4 && vector && !arrows)
      arrows = &view;
    else if (!colour)
      colour = &view;
  }
  const auto hasArrows = [&] {
    return std::any_of(instance.annotations.begin(), instance.annotations.end(),
                       [](const AnnotationSpec& spec) { return std::holds_alternative<ArrowSpec>(spec); });
  };
  if (arrows && !hasArrows()) {
    ArrowSpec spec;
    spec.field = nameOf(*arrows);
    spec.where = SourceLocation{path, arrows->line, 1};
    instance.annotations.push_back(spec);
  }
  // gmsh's way to show stress on a deformed shape: the displacement view coloured by another view,
  // usually hidden itself.
  GmshPostView external;
  if (displacement && displacement->externalView >= 0 && displacement->externalView != displacement->index) {
    const auto named = std::find_if(views.begin(), views.end(), [&](const GmshPostView& view) {
      return view.index == displacement->externalView;
    });
    external.index = displacement->externalView;
    external.line = displacement->line;
    colour = named != views.end() ? &*named : &external;
  }
  if (displacement && !instance.warp) {
    WarpSettings warp;
    warp.field = nameOf(*displacement);
    warp.factor = displacement->displacementFactor;
    warp.where = SourceLocation{path, displacement->line, 1};
    instance.warp = warp;
  }
  if (!colour) colour = displacement;
  if (!colour) return;
  ColorBy color = instance.colorBy.value_or(ColorBy{});
  if (!instance.colorBy) {
    color.field = nameOf(*colour);
    color.where = SourceLocation{path, colour->line, 1};
    // gmsh shows a tensor view's von Mises value (View.TensorType = 1, its default).
    const std::vector<const MeshField*> steps = viewSteps(mesh, color.field);
    if (!steps.empty() && steps.front()->components == 9)
      color.component.kind = FieldComponent::Kind::VonMises;
    color.map =
        *ColorMap::named(fmt::format("gmsh:{}{}", colour->colormapNumber, colour->colormapSwap ? "_r" : ""));
  }
  if (colour->rangeType == 2 && colour->customMin < colour->customMax)
    color.range = std::pair{colour->customMin, colour->customMax};
  color.perStepRange = colour->rangeType == 3;
  // gmsh's colour scale: a horizontal bar along the bottom (View.AutoPosition), or none.
  if (!color.legend) color.legend = colour->showScale ? LegendPlacement::Bottom : LegendPlacement::None;
  const int nbIso = std::clamp(colour->nbIso, 1, 1000);
  if (colour->intervalsType == 3 && color.bands == 0) color.bands = nbIso;  // discrete: filled bands
  if (colour->intervalsType == 1 && !instance.isolines) {
    // Iso-values: lines at gmsh's values in the map's colours, on the surface's own material (gmsh
    // leaves the surface unfilled; a ray-traced part keeps its shape and shadows).
    color.paintsSurface = false;
    IsolineSpec lines;
    lines.colorFromMap = true;
    lines.field = color.field;
    lines.step = color.step;
    lines.component = color.component;
    lines.count = nbIso;
    lines.colorRangeEnds = true;
    lines.where = SourceLocation{path, colour->line, 1};
    instance.isolines = lines;
  }
  instance.colorBy = color;
  if (colour->timeStep && !description.when.step) {
    const std::vector<const MeshField*> steps = viewSteps(mesh, color.field);
    const int k = *colour->timeStep;
    if (k < 0 || k >= static_cast<int>(steps.size()))
      throw InputError(
          SourceLocation{path, colour->line, 1},
          fmt::format("View[{}].TimeStep = {}, but the view \"{}\" of {} has {} step{}: give 0 to {}",
                      colour->index, k, color.field, mesh.source.path, steps.size(),
                      steps.size() == 1 ? "" : "s", steps.empty() ? 0 : steps.size() - 1));
    description.when = StepSelection{steps[static_cast<std::size_t>(k)]->step, std::nullopt,
                                     fmt::format("View[{}].TimeStep in {}", colour->index, path)};
  }
}

}  // namespace lancer
