// The [mesh] keys of volume views: [[mesh.slice]], `skin`, `isosurfaces` and `streamlines`, read into
// the instance's VolumeViews (results/volume_view_spec.hpp) with their checks and messages.
#include "lancer/scene/results/volume_view_text.hpp"
#include "lancer/scene/results/volume_views.hpp"

#include <fmt/format.h>

#include <string>
#include <string_view>
#include <vector>

namespace lancer {

namespace {

// The inline table `key` of a [mesh] for a view of one field, with that field and its step read:
// nothing when the key is absent. `example` is what the key's error shows; `fieldHint` what the
// missing field's does.
struct FieldViewTable {
  TomlTableReader reader;
  SourceLocation where;
  std::string field;
  std::optional<int> step;
};
std::optional<FieldViewTable> readFieldViewTable(const TomlTableReader& mesh, std::string_view key,
                                                 const char* example, const char* fieldHint,
                                                 SceneTable kind) {
  const toml::node* node = mesh.find(key);
  if (!node) return std::nullopt;
  const auto* table = node->as_table();
  if (!table)
    mesh.fail(*node, fmt::format("{} must be a table like {}, found {}", mesh.qualified(key), example,
                                 describeValue(*node)));
  FieldViewTable view{
      TomlTableReader(*table, mesh.qualified(key), mesh.file(), kind), mesh.location(*node), {}, {}};
  const std::optional<std::string> field = view.reader.nonEmptyString("field");
  if (!field) view.reader.failMissing("field", fieldHint);
  view.field = *field;
  if (auto step = view.reader.integer("step", 0, 1'000'000'000)) view.step = static_cast<int>(*step);
  return view;
}

}  // namespace

SliceSpec readSlice(const TomlTableReader& reader) {
  SliceSpec slice;
  slice.where = reader.location(reader.table());
  if (auto point = reader.vector("point", Triple::Xyz)) slice.point = *point;
  const std::optional<Vec3d> normal = reader.vector("normal", Triple::Xyz);
  if (!normal) reader.failMissing("normal", "normal = [x, y, z] (the plane's normal)");
  if (length(*normal) == 0.0)
    reader.fail(*reader.find("normal"), fmt::format("{} must not be [0, 0, 0]", reader.qualified("normal")));
  slice.normal = normalize(*normal);
  return slice;
}

void readVolumeViewKeys(const TomlTableReader& mesh, MeshInstance& instance) {
  readStreamlineKeys(mesh, instance);
  if (auto skin = mesh.choice("skin", kSkinStyles)) instance.volume.skin = static_cast<SkinStyle>(*skin);
  const std::optional<FieldViewTable> view =
      readFieldViewTable(mesh, "isosurfaces", "{ field = \"v\", count = 5 }",
                         "field = \"v\" (a scalar field of the volume)", SceneTable::MeshIsosurfaces);
  if (!view) return;
  const TomlTableReader& reader = view->reader;
  IsosurfaceSpec spec;
  spec.where = view->where;
  spec.field = view->field;
  spec.step = view->step;
  if (auto count = reader.integer("count", 1, kMaxIsosurfaces)) spec.count = static_cast<int>(*count);
  if (const toml::node* values = reader.find("values")) {
    const auto* array = values->as_array();
    if (!array || array->empty() || array->size() > kMaxIsosurfaces)
      reader.fail(*values, fmt::format("{} must be an array of 1 to {} numbers, found {}",
                                       reader.qualified("values"), kMaxIsosurfaces, describeValue(*values)));
    for (const toml::node& item : *array) {
      const double value = item.is_number() ? item.value<double>().value_or(NAN) : NAN;
      if (!std::isfinite(value) || std::abs(value) > std::numeric_limits<float>::max())
        reader.fail(item, fmt::format("{} must hold finite numbers, found {}", reader.qualified("values"),
                                      describeValue(item)));
      spec.values.push_back(value);
    }
    if (reader.find("count"))
      reader.fail(*values, fmt::format("{} gives both count and values: keep one", reader.label()));
  }
  if (auto color = reader.vector("color", Triple::Rgb, NumberRange::between(0, 1)))
    spec.color = toFloat(*color);
  if (auto colorBy = reader.nonEmptyString("color_by")) spec.colorBy = *colorBy;
  if (spec.color && spec.colorBy)
    reader.fail(*reader.find("color"),
                fmt::format("{} gives both color and color_by: keep one", reader.label()));
  instance.volume.isosurfaces = spec;
}

namespace {

constexpr std::array<std::string_view, 3> kDirections = {"both", "forward", "backward"};

// An array of [x, y, z] points (seed_line: exactly two).
std::vector<Vec3d> readPoints(const TomlTableReader& reader, std::string_view key, std::size_t least,
                              std::size_t most) {
  std::vector<Vec3d> points;
  const toml::node* node = reader.find(key);
  if (!node) return points;
  const auto* array = node->as_array();
  const std::string expected = least == most ? fmt::format("{} points [x, y, z]", least)
                                             : fmt::format("{} to {} points [x, y, z]", least, most);
  if (!array || array->size() < least || array->size() > most)
    reader.fail(*node, fmt::format("{} must be an array of {}, found {}", reader.qualified(key), expected,
                                   describeValue(*node)));
  for (std::size_t i = 0; i < array->size(); ++i)
    points.push_back(reader.checkedVector(*array->get(i), fmt::format("{}[{}]", reader.qualified(key), i),
                                          Triple::Xyz, NumberRange::any(), ""));
  return points;
}

// `seed_rectangle = [[x, y, z], [ux, uy, uz], [vx, vy, vz]]`: a corner and the two edges from it,
// neither of zero length nor the two parallel.
void readSeedRectangle(const TomlTableReader& reader, StreamlineSpec& spec) {
  const std::vector<Vec3d> given = readPoints(reader, "seed_rectangle", 3, 3);
  const toml::node& node = *reader.find("seed_rectangle");
  const std::string name = reader.qualified("seed_rectangle");
  for (std::size_t k = 1; k < 3; ++k)
    if (!(length(given[k]) > 0))
      reader.fail(node,
                  fmt::format("{} is a corner and the two edges from it, [[x, y, z], [ux, uy, uz], [vx, vy, "
                              "vz]]: its edge {} is [0, 0, 0]; give it a length",
                              name, k == 1 ? "u" : "v"));
  if (!(length(cross(normalize(given[1]), normalize(given[2]))) > 1e-6))
    reader.fail(node, fmt::format("{}: its two edges are parallel, so the rectangle has no area; give edges "
                                  "along two directions",
                                  name));
  spec.rectangleCorner = given[0];
  spec.rectangleEdgeU = given[1];
  spec.rectangleEdgeV = given[2];
}

// `radius = 0.01` (model units) or `radius = "2px"` (pixels of the picture).
void readTubeRadius(const TomlTableReader& reader, StreamlineSpec& spec) {
  const toml::node* node = reader.find("radius");
  if (!node) return;
  if (!node->is_string()) {
    spec.radius = reader.number("radius", NumberRange::above(0));
    return;
  }
  const std::string text = node->value<std::string>().value_or("");
  const std::optional<double> pixels = pixelsFromText(text);
  if (!pixels || !(*pixels > 0) || *pixels > kMaxRadiusPixels)
    reader.fail(*node,
                fmt::format("{} must be a length in model units (0.01) or in pixels greater than 0 and "
                            "at most {:g} (\"2px\"), found \"{}\"",
                            reader.qualified("radius"), kMaxRadiusPixels, text));
  spec.radiusPixels = *pixels;
}

}  // namespace

void readStreamlineKeys(const TomlTableReader& mesh, MeshInstance& instance) {
  const std::optional<FieldViewTable> view =
      readFieldViewTable(mesh, "streamlines", "{ field = \"e\", count = 50 }",
                         "field = \"e\" (a vector field of the volume)", SceneTable::MeshStreamlines);
  if (!view) return;
  const TomlTableReader& reader = view->reader;
  StreamlineSpec spec;
  spec.where = view->where;
  spec.field = view->field;
  spec.step = view->step;
  if (auto count = reader.integer("count", 1, kMaxStreamlines)) spec.count = static_cast<int>(*count);
  int seedKinds = 0;
  if (reader.find("seed_line")) {
    spec.seeds = StreamlineSpec::Seeds::Line;
    spec.points = readPoints(reader, "seed_line", 2, 2);
    ++seedKinds;
  }
  if (reader.find("seed_points")) {
    spec.seeds = StreamlineSpec::Seeds::Points;
    spec.points = readPoints(reader, "seed_points", 1, kMaxStreamlines);
    ++seedKinds;
  }
  if (reader.find("seed_center") || reader.find("seed_radius") || reader.find("seed_normal")) {
    spec.seeds = StreamlineSpec::Seeds::Disk;
    const std::optional<Vec3d> center = reader.vector("seed_center", Triple::Xyz);
    const std::optional<double> radius = reader.number("seed_radius", NumberRange::above(0));
    if (!center || !radius)
      reader.fail(reader.table(),
                  fmt::format("{}: a disk of seeds needs seed_center = [x, y, z] and seed_radius (and "
                              "seed_normal, default [0, 0, 1])",
                              reader.label()));
    spec.diskCenter = *center;
    spec.diskRadius = *radius;
    if (auto normal = reader.vector("seed_normal", Triple::Xyz)) {
      if (length(*normal) == 0)
        reader.fail(*reader.find("seed_normal"),
                    fmt::format("{} must not be [0, 0, 0]", reader.qualified("seed_normal")));
      spec.diskNormal = normalize(*normal);
    }
    ++seedKinds;
  }
  if (reader.find("seed_rectangle")) {
    spec.seeds = StreamlineSpec::Seeds::Rectangle;
    readSeedRectangle(reader, spec);
    ++seedKinds;
  }
  if (seedKinds > 1)
    reader.fail(reader.table(),
                fmt::format("{} gives seeds more than one way (seed_line, seed_points, a seed disk, "
                            "seed_rectangle): keep one",
                            reader.label()));
  readTubeRadius(reader, spec);
  if (auto length = reader.number("max_length", NumberRange::above(0))) spec.maxLength = *length;
  if (auto direction = reader.choice("direction", kDirections)) {
    spec.forward = *direction != 2;
    spec.backward = *direction != 1;
  }
  if (auto color = reader.vector("color", Triple::Rgb, NumberRange::between(0, 1)))
    spec.color = toFloat(*color);
  if (auto colorBy = reader.nonEmptyString("color_by")) spec.colorBy = *colorBy;
  if (spec.color && spec.colorBy)
    reader.fail(*reader.find("color"),
                fmt::format("{} gives both color and color_by: keep one", reader.label()));
  instance.volume.streamlines = spec;
}

}  // namespace lancer
