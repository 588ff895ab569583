#include "lancer/mesh/field_steps.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace lancer {

std::optional<FieldComponent> parseFieldComponent(std::string_view text) {
  using Kind = FieldComponent::Kind;
  if (text == "magnitude") return FieldComponent{Kind::Magnitude, 0};
  if (text == "von_mises") return FieldComponent{Kind::VonMises, 0};
  if (text == "x" || text == "y" || text == "z") return FieldComponent{Kind::Index, text[0] - 'x'};
  int index = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
  if (!text.empty() && error == std::errc() && end == text.data() + text.size() && index >= 0 && index < 9)
    return FieldComponent{Kind::Index, index};
  return std::nullopt;
}

std::string describeComponent(const FieldComponent& component) {
  switch (component.kind) {
    case FieldComponent::Kind::Magnitude:
      return "magnitude";
    case FieldComponent::Kind::VonMises:
      return "von_mises";
    case FieldComponent::Kind::Index:
      break;
  }
  return fmt::format("component {}", component.index);
}

std::string componentProblem(const FieldComponent& component, int components) {
  const std::string kind = components == 1   ? "a scalar (1 component)"
                           : components == 3 ? "a vector (3 components)"
                           : components == 9 ? "a tensor (9 components)"
                                             : fmt::format("{} components", components);
  if (component.kind == FieldComponent::Kind::VonMises && components != 9)
    return fmt::format(
        "von_mises needs a tensor of 9 components, the view is {}; use \"magnitude\" or 0 to {}", kind,
        components - 1);
  if (component.kind == FieldComponent::Kind::Index && component.index >= components)
    return fmt::format("component {} does not exist: the view is {}; use {}", component.index, kind,
                       components == 1 ? std::string("0 or \"magnitude\"")
                                       : fmt::format("\"magnitude\" or 0 to {}", components - 1));
  return {};
}

float componentScalar(const float* v, int components, const FieldComponent& component) {
  switch (component.kind) {
    case FieldComponent::Kind::Index:
      return v[component.index];
    case FieldComponent::Kind::VonMises: {
      const double xx = v[0], yy = v[4], zz = v[8];
      const double xy = 0.5 * (double{v[1]} + v[3]), yz = 0.5 * (double{v[5]} + v[7]),
                   zx = 0.5 * (double{v[2]} + v[6]);
      const double sum = (xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx) +
                         6 * (xy * xy + yz * yz + zx * zx);
      return static_cast<float>(std::sqrt(0.5 * sum));
    }
    case FieldComponent::Kind::Magnitude:
      break;
  }
  if (components == 1) return v[0];
  double sum = 0;
  for (int c = 0; c < components; ++c) sum += static_cast<double>(v[c]) * v[c];
  return static_cast<float>(std::sqrt(sum));
}

std::pair<double, double> componentRange(const MeshField& field, const FieldComponent& component) {
  if (!field.ranges.empty()) {
    const auto components = static_cast<std::size_t>(field.components);
    const std::size_t slot = component.kind == FieldComponent::Kind::Index
                                 ? static_cast<std::size_t>(component.index)
                             : component.kind == FieldComponent::Kind::VonMises ? components + 1
                                                                                : components;
    const std::vector<std::pair<float, float>>& ranges = field.ranges;
    if (slot < ranges.size() && ranges[slot].first <= ranges[slot].second)
      return {ranges[slot].first, ranges[slot].second};
    return {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  }
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 0; i < field.itemCount(); ++i) {
    const double value = componentScalar(field.values.data() + i * static_cast<std::size_t>(field.components),
                                         field.components, component);
    if (std::isnan(value)) continue;
    low = std::min(low, value);
    high = std::max(high, value);
  }
  return {low, high};
}

std::vector<std::pair<float, float>> componentRanges(const std::vector<float>& values, int components) {
  const float none = std::numeric_limits<float>::infinity();
  std::vector<std::pair<float, float>> ranges(
      static_cast<std::size_t>(components) + (components == 9 ? 2 : 1), {none, -none});
  const auto include = [](std::pair<float, float>& range, float value) {
    if (std::isnan(value)) return;
    range.first = std::min(range.first, value);
    range.second = std::max(range.second, value);
  };
  const auto n = static_cast<std::size_t>(components);
  for (std::size_t i = 0; i + n <= values.size(); i += n) {
    const float* v = values.data() + i;
    for (std::size_t c = 0; c < n; ++c) include(ranges[c], v[c]);
    include(ranges[n], componentScalar(v, components, FieldComponent{}));
    if (components == 9)
      include(ranges[n + 1], componentScalar(v, components, {FieldComponent::Kind::VonMises, 0}));
  }
  return ranges;
}

namespace {}  // namespace

bool timedByTags(std::vector<const MeshField*> steps) {
  std::sort(steps.begin(), steps.end(),
            [](const MeshField* a, const MeshField* b) { return a->step < b->step; });
  for (std::size_t i = 1; i < steps.size(); ++i)
    if (!(steps[i]->time > steps[i - 1]->time)) return false;
  return true;
}

std::vector<const MeshField*> viewSteps(const Mesh& mesh, std::string_view name) {
  std::vector<const MeshField*> steps;
  for (const MeshField& field : mesh.fields)
    if (field.name == name) steps.push_back(&field);
  const bool byTime = timedByTags(steps);
  std::stable_sort(steps.begin(), steps.end(), [&](const MeshField* a, const MeshField* b) {
    if (byTime && a->time != b->time) return a->time < b->time;
    return a->step < b->step;
  });
  return steps;
}

double stepTime(const std::vector<const MeshField*>& steps, std::size_t i) {
  return timedByTags(steps) ? steps[i]->time : static_cast<double>(steps[i]->step);
}

std::vector<std::string> viewNames(const Mesh& mesh) {
  std::vector<std::string> names;
  for (const MeshField& field : mesh.fields)
    if (std::find(names.begin(), names.end(), field.name) == names.end()) names.push_back(field.name);
  return names;
}

std::string describeViews(const Mesh& mesh) {
  std::string text;
  for (const std::string& name : viewNames(mesh)) {
    std::vector<int> steps;
    for (const MeshField* field : viewSteps(mesh, name)) steps.push_back(field->step);
    const std::string list = steps.size() > 6 ? fmt::format("{} to {}", steps.front(), steps.back())
                                              : fmt::format("{}", fmt::join(steps, ", "));
    text += fmt::format("{}\"{}\" (step{} {})", text.empty() ? "" : ", ", name, steps.size() > 1 ? "s" : "",
                        list);
  }
  return text;
}

std::optional<ViewValues> viewValuesAt(const std::vector<const MeshField*>& steps, const StepSelection& when,
                                       std::string& problem) {
  if (steps.empty()) return std::nullopt;
  ViewValues view;
  auto one = [&](const MeshField& field) {
    view.field = &field;
    view.a = &fieldValues(field, view.keepA);
    return std::optional<ViewValues>(std::move(view));
  };
  if (when.step || !when.time) {
    const int wanted = when.step.value_or(steps.front()->step);
    for (const MeshField* field : steps)
      if (field->step == wanted) return one(*field);
    std::vector<int> indices;
    indices.reserve(steps.size());
    for (const MeshField* field : steps) indices.push_back(field->step);
    std::sort(indices.begin(), indices.end());
    problem = fmt::format("has no step {}: its steps are {} (give a step from {} to {})", wanted,
                          indices.size() > 6 ? fmt::format("{} to {}", indices.front(), indices.back())
                                             : fmt::format("{}", fmt::join(indices, ", ")),
                          indices.front(), indices.back());
    return std::nullopt;
  }
  const double t = *when.time;
  std::size_t next = 0;
  while (next < steps.size() && stepTime(steps, next) < t) ++next;
  if (next == 0) return one(*steps.front());
  if (next == steps.size()) return one(*steps.back());
  const double t0 = stepTime(steps, next - 1), t1 = stepTime(steps, next);
  if (t1 == t) return one(*steps[next]);
  if (steps[next - 1]->itemCount() != steps[next]->itemCount() ||
      steps[next - 1]->components != steps[next]->components) {
    problem =
        fmt::format("steps {} and {} have different sizes ({} and {} values); they cannot be blended",
                    steps[next - 1]->step, steps[next]->step,
                    steps[next - 1]->itemCount() * static_cast<std::size_t>(steps[next - 1]->components),
                    steps[next]->itemCount() * static_cast<std::size_t>(steps[next]->components));
    return std::nullopt;
  }
  // Read back when stored (the two steps of a blend are the two a stored file keeps), else not copied.
  view.field = steps[next - 1];
  view.a = &fieldValues(*steps[next - 1], view.keepA);
  view.b = &fieldValues(*steps[next], view.keepB);
  view.weight = static_cast<float>((t - t0) / (t1 - t0));
  return view;
}

std::optional<MeshField> viewAt(const std::vector<const MeshField*>& steps, const StepSelection& when,
                                std::string& problem) {
  const std::optional<ViewValues> view = viewValuesAt(steps, when, problem);
  if (!view) return std::nullopt;
  if (!view->b) {  // the step itself, with its ranges
    MeshField field = *view->field;
    if (field.stored) {
      field.stored.reset();
      field.values = *view->a;
    }
    return field;
  }
  MeshField blend;
  blend.name = view->field->name;
  blend.at = view->field->at;
  blend.components = view->field->components;
  blend.step = -1;
  blend.time = *when.time;
  blend.values.resize(view->size());
  for (std::size_t i = 0; i < blend.values.size(); ++i) blend.values[i] = (*view)[i];
  return blend;
}

std::vector<double> stepTimes(const Mesh& mesh, const std::vector<std::string>& names) {
  std::vector<double> times;
  for (const std::string& name : names) {
    const std::vector<const MeshField*> steps = viewSteps(mesh, name);
    for (std::size_t i = 0; i < steps.size(); ++i) times.push_back(stepTime(steps, i));
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

namespace {

// value(i) is the i-th of a corner view's values (kCornerSlots * components per face).
template <typename Value>
std::vector<float> meansAtVertices(const Mesh& mesh, int componentCount, const Value& value) {
  const auto components = static_cast<std::size_t>(componentCount);
  std::vector<double> sum(mesh.positions.size() * components, 0.0);
  std::vector<std::uint32_t> count(mesh.positions.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const MeshFace& face = mesh.faces[f];
    for (int c = 0; c < face.cornerCount(); ++c) {
      const std::size_t first =
          (f * kCornerSlots + static_cast<std::size_t>(cornerSlot(face, c))) * components;
      if (std::isnan(value(first))) continue;
      const std::uint32_t v = face.vertex[c];
      ++count[v];
      for (std::size_t k = 0; k < components; ++k) sum[v * components + k] += value(first + k);
    }
  }
  std::vector<float> means(sum.size(), std::numeric_limits<float>::quiet_NaN());
  for (std::size_t v = 0; v < count.size(); ++v)
    if (count[v])
      for (std::size_t k = 0; k < components; ++k)
        means[v * components + k] = static_cast<float>(sum[v * components + k] / count[v]);
  return means;
}

}  // namespace

ViewValues vertexMeans(const Mesh& mesh, const ViewValues& view) {
  if (view.field->at != FieldAt::kCorner ||
      view.size() != mesh.faces.size() * kCornerSlots * static_cast<std::size_t>(view.field->components))
    return view;
  ViewValues means;
  means.field = view.field;
  means.keepA = std::make_shared<const std::vector<float>>(
      meansAtVertices(mesh, view.field->components, [&](std::size_t i) { return view[i]; }));
  means.a = means.keepA.get();
  return means;
}

MeshField vertexMeans(const Mesh& mesh, const MeshField& field) {
  if (field.at != FieldAt::kCorner || field.isStored() ||
      field.values.size() != mesh.faces.size() * kCornerSlots * static_cast<std::size_t>(field.components))
    return field;
  MeshField means = field;
  means.at = FieldAt::kNode;
  means.values = meansAtVertices(mesh, field.components, [&](std::size_t i) { return field.values[i]; });
  means.ranges.clear();
  return means;
}

}  // namespace lancer
