// Reading what asks for arrows: the [[mesh]] key `arrows = { ... }` and the command line's text.
#include <fmt/format.h>

#include <array>
#include <charconv>
#include <string_view>

#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/arrows.hpp"

namespace lancer {
namespace {

// What is wrong with a grid of `points` arrows (each axis already >= 1), or "" when nothing is: the
// product is checked in 64 bits before anything is allocated for it.
std::string gridProblem(const std::array<std::int64_t, 3>& points) {
  const std::int64_t total = points[0] * points[1] * points[2];  // each <= kMaxArrowCount: no overflow
  if (total <= kMaxArrowCount) return "";
  return fmt::format(
      "{} x {} x {} = {} points, more than the {} arrows a mesh may have; give fewer points "
      "along each axis",
      points[0], points[1], points[2], total, kMaxArrowCount);
}

std::array<int, 3> readGrid(const TomlTableReader& reader, const toml::node& node) {
  const auto* array = node.as_array();
  if (!array || array->size() != 3)
    reader.fail(node,
                fmt::format("{} must be an array of three integers [nx, ny, nz] (points along x, y and z), "
                            "found {}",
                            reader.qualified("grid"), describeValue(node)));
  std::array<std::int64_t, 3> points{};
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::node& item = *array->get(i);
    const std::optional<std::int64_t> value = item.value_exact<std::int64_t>();
    if (!value || *value < 1 || *value > kMaxArrowCount)
      reader.fail(item, fmt::format("{}[{}] must be an integer from 1 to {}, found {}",
                                    reader.qualified("grid"), i, kMaxArrowCount, describeValue(item)));
    points[i] = *value;
  }
  if (const std::string problem = gridProblem(points); !problem.empty())
    reader.fail(node, fmt::format("{} asks for {}", reader.qualified("grid"), problem));
  return {static_cast<int>(points[0]), static_cast<int>(points[1]), static_cast<int>(points[2])};
}

}  // namespace

std::optional<ArrowSpec> readArrows(const std::string& file, const TomlTableReader& mesh) {
  const toml::node* node = mesh.find("arrows");
  if (!node) return std::nullopt;
  const auto* table = node->as_table();
  if (!table)
    mesh.fail(*node,
              fmt::format("{} must be a table like {{ field = \"velocity\", max_count = 500 }}, found {}",
                          mesh.qualified("arrows"), describeValue(*node)));
  const TomlTableReader reader(*table, mesh.qualified("arrows"), file, SceneTable::MeshArrows);
  ArrowSpec spec;
  spec.where = reader.location(*node);
  const std::optional<std::string> field = reader.nonEmptyString("field");
  if (!field) reader.failMissing("field", "field = \"velocity\" (a view of 3 components)");
  spec.field = *field;
  if (auto step = reader.integer("step", 0, 1'000'000'000)) spec.step = static_cast<int>(*step);
  if (auto count = reader.integer("max_count", 1, kMaxArrowCount)) spec.maxCount = static_cast<int>(*count);
  if (const toml::node* grid = reader.find("grid")) {
    if (reader.find("max_count"))
      reader.fail(*grid, fmt::format("{} and {} both say where arrows go: give max_count for arrows on the "
                                     "surface, or grid for arrows through the volume",
                                     reader.qualified("grid"), reader.qualified("max_count")));
    spec.grid = readGrid(reader, *grid);
  }
  if (const toml::node* scale = reader.find("scale")) {
    if (!(scale->is_string() && scale->value<std::string>() == "auto")) {
      if (!scale->is_number())
        reader.fail(*scale, fmt::format("{} must be \"auto\" or a number > 0, found {}",
                                        reader.qualified("scale"), describeValue(*scale)));
      spec.scale = reader.number("scale", NumberRange::above(0));
    }
  }
  constexpr std::array<std::string_view, 2> kLengths = {"magnitude", "fixed"};
  if (auto length = reader.choice("length", kLengths)) spec.fixedLength = *length == 1;
  if (auto color = reader.vector("color", Triple::Rgb, NumberRange::between(0, 1)))
    spec.color = toFloat(*color);
  return spec;
}

std::array<int, 3> arrowGridFromText(const std::string& text, const std::string& option) {
  std::array<std::int64_t, 3> points{};
  std::string_view rest = text;
  bool parsed = true;
  for (std::size_t i = 0; i < 3 && parsed; ++i) {
    const std::size_t comma = i < 2 ? rest.find(',') : std::string_view::npos;
    const std::string_view item = rest.substr(0, comma);
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), points[i]);
    parsed = error == std::errc{} && end == item.data() + item.size() && points[i] >= 1 &&
             points[i] <= kMaxArrowCount && (i == 2 || comma != std::string_view::npos);
    if (comma != std::string_view::npos) rest.remove_prefix(comma + 1);
  }
  if (!parsed)
    throw InputError(SourceLocation{option},
                     fmt::format("'{}' is not NX,NY,NZ: give three integers from 1 to {} (points along x, y "
                                 "and z), e.g. {} 8,8,8",
                                 text, kMaxArrowCount, option));
  if (const std::string problem = gridProblem(points); !problem.empty())
    throw InputError(SourceLocation{option}, fmt::format("'{}' asks for {}", text, problem));
  return {static_cast<int>(points[0]), static_cast<int>(points[1]), static_cast<int>(points[2])};
}

ArrowSpec arrowsOfField(const std::string& field, const SourceLocation& where) {
  ArrowSpec spec;
  spec.field = field;
  spec.where = where;
  return spec;
}

std::optional<AnnotationSpec> readArrowAnnotation(const std::string& file, const TomlTableReader& mesh) {
  if (std::optional<ArrowSpec> spec = readArrows(file, mesh)) return AnnotationSpec{std::move(*spec)};
  return std::nullopt;
}

}  // namespace lancer
