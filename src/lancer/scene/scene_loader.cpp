#include "lancer/scene/scene_loader.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "lancer/scene/animation_keys.hpp"
#include "lancer/scene/light_loader.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/annotation_kinds.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "lancer/scene/results/volume_views.hpp"
#include "lancer/scene/scene_from_toml.hpp"
#include "lancer/scene/suggest.hpp"
#include "lancer/scene/toml_table_reader.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer {
namespace {

constexpr std::array<std::string_view, 2> kEncodingNames = {"srgb", "linear"};
constexpr std::array<std::string_view, 2> kEdgeSelections = {"elements", "features"};
// State shared by the section readers: the file for messages and the folder paths are relative to.
struct SceneFile {
  std::string path;
  std::filesystem::path folder;

  std::string resolve(const std::string& relative) const {
    const std::filesystem::path value(relative);
    if (value.is_absolute()) return relative;
    return (folder / value).lexically_normal().string();
  }
  [[noreturn]] void fail(const toml::node& node, const std::string& message) const {
    throw InputError(locate(path, node.source()), message);
  }
};

std::string formatVector(const Vec3d& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

// `[render]`, `[camera]`, ... : a table if present, nullptr if absent.
const toml::table* sectionTable(const SceneFile& file, const toml::table& root, std::string_view name) {
  const toml::node* node = root.get(name);
  if (!node) return nullptr;
  if (const auto* table = node->as_table()) return table;
  file.fail(*node,
            fmt::format("{} must be a table written [{}], found {}", name, name, describeValue(*node)));
}

// `[[light]]`, `[[mesh]]`, `[[mesh.clip]]`: the elements of the array of tables `key` of `parent`
// (empty if absent). `name` is how messages call it ("mesh[2].clip"), `header` how it is written
// ("mesh.clip").
std::vector<const toml::table*> tableArray(const SceneFile& file, const toml::table& parent,
                                           std::string_view key, std::string_view name,
                                           std::string_view header) {
  std::vector<const toml::table*> tables;
  const toml::node* node = parent.get(key);
  if (!node) return tables;
  const auto* array = node->as_array();
  if (!array)
    file.fail(*node,
              fmt::format("{} must be an array of tables: write [[{}]] for each one, not {}", name, header,
                          node->is_table() ? fmt::format("[{}]", header) : describeValue(*node)));
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    if (!element.is_table())
      file.fail(element, fmt::format("{}[{}] must be a table written [[{}]], found {}", name, i, header,
                                     describeValue(element)));
    tables.push_back(element.as_table());
  }
  return tables;
}

std::vector<const toml::table*> tableArray(const SceneFile& file, const toml::table& root,
                                           std::string_view name) {
  return tableArray(file, root, name, name, name);
}

void readBackground(const TomlTableReader& reader, RenderSettings& render) {
  const toml::node* node = reader.find("background");
  if (!node) return;
  if (const auto* text = node->as_string()) {
    constexpr std::array<std::string_view, 1> kWords = {"transparent"};
    if (text->get() != kWords[0])
      reader.fail(*node, fmt::format("render.background must be [r, g, b] or \"transparent\", found \"{}\"{}",
                                     text->get(), didYouMean(text->get(), kWords)));
    render.transparentBackground = true;
    return;
  }
  if (!node->is_array())
    reader.fail(*node, fmt::format("render.background must be [r, g, b] or \"transparent\", found {}",
                                   describeValue(*node)));
  render.background = toFloat(*reader.vector("background", Triple::Rgb, NumberRange::atLeast(0)));
}

// encoding (or the older srgb = true | false), tonemap, exposure, bit_depth, denoise, quality, lossless,
// dpi: docs/output.md.
void readOutputKeys(const TomlTableReader& reader, RenderSettings& render) {
  if (auto srgb = reader.boolean("srgb")) render.srgb = *srgb;
  if (auto encoding = reader.choice("encoding", kEncodingNames)) {
    if (reader.find("srgb"))
      reader.fail(*reader.find("encoding"),
                  "render.encoding and render.srgb both say how the image is encoded; keep encoding (srgb = "
                  "false is encoding = \"linear\")");
    render.srgb = *encoding == 0;
  }
  if (auto toneMap = reader.choice("tonemap", kToneMapNames)) render.toneMap = static_cast<ToneMap>(*toneMap);
  if (auto exposure = reader.number("exposure"))
    render.exposure = checkExposure(*exposure, reader.settingName("exposure"));
  if (auto bits = reader.integer("bit_depth"))
    render.bitDepth = checkBitDepth(*bits, reader.settingName("bit_depth"));
  if (auto denoise = reader.boolean("denoise")) render.denoise = *denoise;
  // quality, lossless, dpi: how JPEG and WebP are compressed, the resolution every format records.
  if (auto quality = reader.integer("quality", std::numeric_limits<std::int64_t>::min(),
                                    std::numeric_limits<std::int64_t>::max())) {
    requireImageQuality(*quality, reader.location(*reader.find("quality")));
    render.quality = static_cast<int>(*quality);
  }
  if (auto lossless = reader.boolean("lossless")) render.lossless = *lossless;
  if (auto dpi = reader.number("dpi", NumberRange::any())) {
    requireDpi(*dpi, reader.location(*reader.find("dpi")));
    render.dpi = *dpi;
  }
}

RenderSettings readRender(const SceneFile& file, const toml::table& table) {
  const TomlTableReader reader(table, "render", file.path, SceneTable::Render);
  RenderSettings render;
  if (auto width = reader.integer("width")) render.width = checkWidth(*width, reader.settingName("width"));
  if (auto height = reader.integer("height"))
    render.height = checkHeight(*height, reader.settingName("height"));
  if (auto sampler = reader.choice("sampler", kSamplerNames))
    render.sampler = static_cast<SamplerKind>(*sampler);
  if (auto integrator = reader.choice("integrator", kIntegratorNames))
    render.integrator = static_cast<IntegratorKind>(*integrator);
  if (auto samples = reader.integer("samples")) {
    render.samples = checkSamples(*samples, reader.settingName("samples"));
    checkSampleGrid(render.samples, render.sampler, render.integrator, reader.settingName("samples"));
  }
  if (auto depth = reader.integer("max_depth"))
    render.maxDepth = checkMaxDepth(*depth, reader.settingName("max_depth"));
  if (auto threshold = reader.number("adaptive_threshold", NumberRange::above(0)))
    render.adaptiveThreshold = static_cast<float>(*threshold);
  if (auto shading = reader.choice("shading", kShadingNames))
    render.shading = static_cast<ShadingMode>(*shading);
  readBackground(reader, render);
  if (auto output = reader.nonEmptyString("output")) render.output = file.resolve(*output);
  readOutputKeys(reader, render);
  if (auto bounces = reader.integer("max_bounces", 0, kMaxDepth))
    render.maxBounces = static_cast<int>(*bounces);
  if (auto noise = reader.number("noise")) render.noise = checkNoise(*noise, reader.settingName("noise"));
  if (auto noise = reader.number("adaptive_noise"))
    render.adaptiveNoise = checkAdaptiveNoise(*noise, reader.settingName("adaptive_noise"));
  if (auto distance = reader.number("ao_distance", NumberRange::above(0)))
    render.aoDistance = static_cast<float>(*distance);
  return render;
}

// `[render] step = K`: the step of the results every mesh shows (colours and warps).
StepSelection readRenderStep(const SceneFile& file, const toml::table& table) {
  const TomlTableReader reader(table, "render", file.path, SceneTable::Render);
  StepSelection when;
  if (auto step = reader.integer("step", 0, 1'000'000'000)) {
    when.step = static_cast<int>(*step);
    const SourceLocation where = reader.location(*reader.find("step"));
    when.where = fmt::format("render.step at {}:{}", where.file, where.line);
  }
  return when;
}

// A camera needs a direction (position != look_at) and an up that is not along it.
void checkCameraFrame(const TomlTableReader& reader, const CameraSettings& camera) {
  const Vec3d up = camera.up;
  if (length(up) == 0) reader.fail(*reader.find("up"), "camera.up must not be [0, 0, 0]; use e.g. [0, 1, 0]");
  if (!camera.position || !camera.lookAt) return;
  const Vec3d view = *camera.lookAt - *camera.position;
  if (length(view) == 0)
    reader.fail(*reader.find("look_at"),
                fmt::format("camera.look_at is the same point as camera.position {}; the camera needs a "
                            "direction to look in",
                            formatVector(*camera.position)));
  constexpr double kMinSine = 1e-6;
  if (!reader.find("up") || length(cross(normalize(up), normalize(view))) >= kMinSine) return;
  // Offer the coordinate axis least aligned with the line of sight.
  const Vec3d direction = abs(normalize(view));
  const Vec3d suggestion = direction.y <= direction.x && direction.y <= direction.z ? Vec3d{0, 1, 0}
                           : direction.z <= direction.x                             ? Vec3d{0, 0, 1}
                                                                                    : Vec3d{1, 0, 0};
  reader.fail(
      *reader.find("up"),
      fmt::format("camera.up {} is parallel to the view direction (look_at - position = {}); choose an up "
                  "across the line of sight, e.g. up = {}",
                  formatVector(up), formatVector(view), formatVector(suggestion)));
}

CameraSettings readCamera(const SceneFile& file, const toml::table& table) {
  const TomlTableReader reader(table, "camera", file.path, SceneTable::Camera);
  CameraSettings camera;
  if (auto projection = reader.choice("projection", kProjectionNames))
    camera.projection = static_cast<Projection>(*projection);
  camera.position = reader.vector("position", Triple::Xyz);
  camera.lookAt = reader.vector("look_at", Triple::Xyz);
  if (auto up = reader.vector("up", Triple::Xyz)) camera.up = *up;
  // up_axis: the up of the automatic camera, which then takes its 3/4 view from that side too.
  if (auto upAxis = reader.choice("up_axis", kUpAxisNames)) {
    if (reader.find("up"))
      reader.fail(
          *reader.find("up_axis"),
          fmt::format("camera.up_axis and camera.up both say which way is up; keep one (up_axis = \"{}\" "
                      "is up = {})",
                      kUpAxisNames[static_cast<std::size_t>(*upAxis)],
                      formatVector(upVector(static_cast<UpAxis>(*upAxis)))));
    applyUpAxis(camera, static_cast<UpAxis>(*upAxis));
  }
  if (auto fov = reader.number("fov", NumberRange::strictlyBetween(0, 180))) camera.fovDegrees = *fov;
  camera.viewHeight = reader.number("view_height", NumberRange::above(0));
  checkCameraFrame(reader, camera);
  // A view the file chose: a flat scene is then not turned straight on (frameFlatScene).
  for (const std::string_view key : {"position", "up", "up_axis", "projection"})
    if (reader.find(key)) camera.viewChosen = true;
  // gmsh_view: the view saved by gmsh (File > Save Model Options), which sets the whole camera.
  if (auto gmshView = reader.string("gmsh_view")) {
    for (const std::string_view key :
         {"projection", "position", "look_at", "up", "up_axis", "fov", "view_height"})
      if (const toml::node* other = reader.find(key))
        reader.fail(*other,
                    fmt::format("camera.{} and camera.gmsh_view both set the camera; gmsh_view sets it "
                                "whole, so keep one",
                                key));
    try {
      camera.gmshView = readGmshView(file.resolve(*gmshView));
    } catch (const InputError& error) {
      if (error.location().line != 0) throw;
      reader.fail(*reader.find("gmsh_view"),
                  fmt::format("camera.gmsh_view: {}: {}", file.resolve(*gmshView), error.message()));
    }
  }
  return camera;
}

// An optional [x, y, z] that must not be zero, returned normalised (plane normals).
std::optional<Vec3d> readDirection(const TomlTableReader& reader, std::string_view key) {
  const std::optional<Vec3d> direction = reader.vector(key, Triple::Xyz);
  if (!direction) return std::nullopt;
  if (length(*direction) == 0.0)
    reader.fail(*reader.find(key), fmt::format("{} must not be [0, 0, 0]", reader.qualified(key)));
  return normalize(*direction);
}

FloorSettings readFloor(const SceneFile& file, const toml::table& table) {
  const TomlTableReader reader(table, "floor", file.path, SceneTable::Floor);
  const std::optional<bool> catcher = reader.boolean("shadow_catcher");
  if (!catcher || !*catcher) {
    if (const toml::node* node = reader.find("shadow_catcher"))
      reader.fail(*node,
                  "floor.shadow_catcher = false is not supported: [floor] is only a shadow catcher; "
                  "for a visible floor add a floor mesh (see examples/demo.toml)");
    reader.failMissing("shadow_catcher", "shadow_catcher = true");
  }
  FloorSettings floor;
  if (auto height = reader.number("height")) floor.height = *height;
  if (auto normal = readDirection(reader, "normal")) floor.normal = *normal;
  return floor;
}

// `[[clip]]` and `[[mesh.clip]]` alike (`kind`); `name` is "clip[1]" or "mesh[0].clip[1]", for messages.
ClipSettings readClip(const SceneFile& file, const toml::table& table, const std::string& name,
                      SceneTable kind) {
  const TomlTableReader reader(table, name, file.path, kind);
  ClipSettings clip;
  const std::optional<Vec3d> point = reader.vector("point", Triple::Xyz);
  if (!point) reader.failMissing("point", "point = [x, y, z] (a point on the cutting plane)");
  const std::optional<Vec3d> normal = readDirection(reader, "normal");
  if (!normal) reader.failMissing("normal", "normal = [x, y, z] (geometry on this side is removed)");
  clip.point = *point;
  clip.normal = *normal;
  if (auto cap = reader.boolean("cap")) clip.cap = *cap;
  return clip;
}

Material readMaterial(const SceneFile& file, const toml::table& table, const std::string& name) {
  const TomlTableReader reader(table, fmt::format("material.{}", name), file.path, SceneTable::Material);
  const NumberRange unit = NumberRange::between(0, 1);
  Material material = defaultMaterial();
  material.name = name;
  if (auto ka = reader.vector("ka", Triple::Rgb, unit)) material.ka = toFloat(*ka);
  if (auto kd = reader.vector("kd", Triple::Rgb, unit)) material.kd = toFloat(*kd);
  if (auto ks = reader.vector("ks", Triple::Rgb, unit)) material.ks = toFloat(*ks);
  if (auto shininess = reader.number("shininess", NumberRange::atLeast(0)))
    material.shininess = static_cast<float>(*shininess);
  if (auto reflectivity = reader.numberOrVector("reflectivity", Triple::Rgb, unit))
    material.reflectivity = toFloat(*reflectivity);
  if (auto transparency = reader.number("transparency", unit))
    material.transparency = static_cast<float>(*transparency);
  if (auto ior = reader.number("ior", NumberRange::above(0))) material.ior = static_cast<float>(*ior);
  if (auto fresnel = reader.boolean("fresnel")) material.fresnel = *fresnel;
  if (auto absorption = reader.vector("absorption", Triple::Rgb, NumberRange::atLeast(0)))
    material.absorption = toFloat(*absorption);
  if (auto emission = reader.vector("emission", Triple::Rgb, NumberRange::atLeast(0)))
    material.emission = toFloat(*emission);
  // Reflected, transmitted and local light share what leaves a point; more than all of it would
  // let each bounce add light (the tracer's energy split, tracer.cpp).
  const float shared = maxComponent(material.reflectivity) + material.transparency;
  if (shared > 1.0f + 1e-6f)
    reader.fail(
        *(reader.find("transparency") ? reader.find("transparency") : reader.find("reflectivity")),
        fmt::format("material.{}: reflectivity + transparency must not exceed 1 in any channel (found "
                    "{:g} + {:g}): they share the light leaving the surface with the local colour; "
                    "lower one of them",
                    name, maxComponent(material.reflectivity), material.transparency));
  return material;
}

// materials[0] is "default" (the built-in one unless the file defines its own); then the file's
// materials in the order they appear.
std::vector<Material> readMaterials(const SceneFile& file, const toml::table& root) {
  std::vector<Material> materials = {defaultMaterial()};
  const toml::table* section = sectionTable(file, root, "material");
  if (!section) return materials;
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (const auto& [key, value] : *section) entries.emplace_back(&key, &value);
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const toml::source_position &pa = a.first->source().begin, &pb = b.first->source().begin;
    return pa.line < pb.line || (pa.line == pb.line && pa.column < pb.column);
  });
  for (const auto& [key, value] : entries) {
    const auto* table = value->as_table();
    if (!table)
      file.fail(*value,
                fmt::format("material.{} must be a table of material keys (ka, kd, ks, shininess, ...), "
                            "found {}; each material is a section [material.NAME]",
                            key->str(), describeValue(*value)));
    Material material = readMaterial(file, *table, std::string(key->str()));
    if (material.name == "default")
      materials[0] = std::move(material);
    else
      materials.push_back(std::move(material));
  }
  return materials;
}

int materialIndex(const SceneFile& file, const toml::node& node, const std::string& what,
                  const std::vector<Material>& materials) {
  const auto* text = node.as_string();
  if (!text)
    file.fail(node,
              fmt::format("{} must be a material name (a string), found {}", what, describeValue(node)));
  std::vector<std::string> names;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    if (materials[i].name == text->get()) return static_cast<int>(i);
    names.push_back(materials[i].name);
  }
  std::string defined;
  for (const std::string& name : names) defined += (defined.empty() ? "" : ", ") + name;
  file.fail(node, fmt::format("{} names material '{}', which is not defined{}; defined materials: {}", what,
                              text->get(), didYouMean(text->get(), names), defined));
}

std::vector<GroupMaterial> readGroupMaterials(const SceneFile& file, const TomlTableReader& mesh,
                                              const std::vector<Material>& materials) {
  std::vector<GroupMaterial> groups;
  const toml::node* node = mesh.find("groups");
  if (!node) return groups;
  const auto* table = node->as_table();
  if (!table)
    mesh.fail(*node, fmt::format("{} must be a table of group = \"material\", e.g. {{ Floor = \"matte\", 7 = "
                                 "\"glass\" }}, found {}",
                                 mesh.qualified("groups"), describeValue(*node)));
  for (const auto& [key, value] : *table) {
    const SourceLocation where = locate(file.path, key.source());
    if (key.str().empty())
      throw InputError(where, fmt::format("{} has an empty group name; use a physical group's name or tag",
                                          mesh.qualified("groups")));
    const std::string what = fmt::format("{}.{}", mesh.qualified("groups"), key.str());
    groups.push_back(
        GroupMaterial{std::string(key.str()), materialIndex(file, value, what, materials), where});
  }
  std::sort(groups.begin(), groups.end(), [](const GroupMaterial& a, const GroupMaterial& b) {
    return a.where.line < b.where.line || (a.where.line == b.where.line && a.where.column < b.where.column);
  });
  return groups;
}

// `edges = { width = 1.0, color = [0, 0, 0], only = "features", feature_angle = 30 }`, or
// `edges = true` for the defaults.
std::optional<EdgeSettings> readEdges(const SceneFile& file, const TomlTableReader& mesh) {
  const toml::node* node = mesh.find("edges");
  if (!node) return std::nullopt;
  if (const auto* enabled = node->as_boolean())
    return enabled->get() ? std::optional<EdgeSettings>(EdgeSettings{}) : std::nullopt;
  const auto* table = node->as_table();
  if (!table)
    mesh.fail(*node,
              fmt::format("{} must be true, false or a table like {{ width = 1.0, color = [0, 0, 0] }}, "
                          "found {}",
                          mesh.qualified("edges"), describeValue(*node)));
  const TomlTableReader reader(*table, mesh.qualified("edges"), file.path, SceneTable::MeshEdges);
  EdgeSettings edges;
  if (auto width = reader.number("width", NumberRange::between(0.1, 100))) edges.widthPixels = float(*width);
  if (auto color = reader.vector("color", Triple::Rgb, NumberRange::between(0, 1)))
    edges.color = toFloat(*color);
  if (auto only = reader.choice("only", kEdgeSelections)) edges.featuresOnly = *only == 1;
  if (auto angle = reader.number("feature_angle", NumberRange::between(0, 180)))
    edges.featureAngleDegrees = float(*angle);
  return edges;
}

// `views = ["az.pos", "b.pos"]`: the files, resolved against the scene file's folder.
std::vector<std::string> readViewFiles(const SceneFile& file, const TomlTableReader& reader) {
  const toml::node* node = reader.find("views");
  if (!node) return {};
  const std::string example =
      "views = [\"az.pos\", \"b.pos\"] (list-based .pos views, relative to the scene file)";
  const auto* list = node->as_array();
  if (!list)
    reader.fail(*node, fmt::format("{} must be an array of file names, {}; found {}",
                                   reader.qualified("views"), example, describeValue(*node)));
  std::vector<std::string> views;
  for (const toml::node& item : *list) {
    const auto* name = item.as_string();
    if (!name || name->get().empty())
      reader.fail(item, fmt::format("{} must hold file names, like {}; found {}", reader.qualified("views"),
                                    example, describeValue(item)));
    views.push_back(file.resolve(name->get()));
  }
  return views;
}

MeshInstance readMesh(const SceneFile& file, const toml::table& table, std::size_t index,
                      const std::vector<Material>& materials) {
  const TomlTableReader reader(table, fmt::format("mesh[{}]", index), file.path, SceneTable::Mesh);
  MeshInstance mesh;
  mesh.where = reader.location(table);
  const std::optional<std::string> path = reader.nonEmptyString("file");
  if (!path) reader.failMissing("file", "file = \"part.msh\" (a gmsh mesh, relative to the scene file)");
  mesh.file = file.resolve(*path);
  mesh.views = readViewFiles(file, reader);
  if (const toml::node* material = reader.find("material"))
    mesh.material = materialIndex(file, *material, reader.qualified("material"), materials);
  if (auto shading = reader.choice("shading", kShadingNames))
    mesh.shading = static_cast<ShadingMode>(*shading);
  if (auto angle = reader.number("smooth_angle", NumberRange::between(0, 180)))
    mesh.smoothAngleDegrees = static_cast<float>(*angle);
  if (auto translate = reader.vector("translate", Triple::Xyz)) mesh.translate = *translate;
  if (auto rotate = reader.vector("rotate", Triple::Xyz)) mesh.rotateDegrees = *rotate;
  if (auto scale = reader.numberOrVector("scale", Triple::Xyz, NumberRange::nonZeroNumber()))
    mesh.scale = *scale;
  mesh.groupMaterials = readGroupMaterials(file, reader, materials);
  mesh.edges = readEdges(file, reader);
  mesh.colorBy = readColorBy(file.path, reader);
  readWarpKeys(reader, mesh);
  mesh.isolines = readIsolines(file.path, reader);
  mesh.annotations = readAnnotations(file.path, reader);
  const std::string clipName = reader.qualified("clip");
  const std::vector<const toml::table*> clips = tableArray(file, table, "clip", clipName, "mesh.clip");
  for (std::size_t i = 0; i < clips.size(); ++i)
    mesh.clips.push_back(readClip(file, *clips[i], fmt::format("{}[{}]", clipName, i), SceneTable::MeshClip));
  const std::string sliceName = reader.qualified("slice");
  const std::vector<const toml::table*> slices = tableArray(file, table, "slice", sliceName, "mesh.slice");
  for (std::size_t i = 0; i < slices.size(); ++i)
    mesh.volume.slices.push_back(readSlice(
        TomlTableReader(*slices[i], fmt::format("{}[{}]", sliceName, i), file.path, SceneTable::MeshSlice)));
  readVolumeViewKeys(reader, mesh);
  return mesh;
}

toml::table parseToml(std::string_view text, const std::string& path) {
  try {
    return toml::parse(text, std::string_view(path));
  } catch (const toml::parse_error& error) {
    throw InputError(locate(path, error.source()), std::string(error.description()));
  }
}

}  // namespace

Material defaultMaterial() {
  Material material;
  material.name = "default";
  material.ka = {0.2f, 0.2f, 0.2f};
  material.kd = {0.7f, 0.7f, 0.7f};
  material.ks = {0.3f, 0.3f, 0.3f};
  material.shininess = 32;
  return material;
}

SceneDescription parseScene(std::string_view text, const std::string& path) {
  return sceneFromToml(parseToml(text, path), path, std::filesystem::path(path).parent_path());
}

SceneDescription sceneFromToml(const toml::table& root, const std::string& path,
                               const std::filesystem::path& folder) {
  const SceneFile file{path, folder};
  const TomlTableReader document(root, "", path, SceneTable::Document);

  SceneDescription scene;
  scene.path = path;
  if (const toml::table* render = sectionTable(file, root, "render")) {
    scene.render = readRender(file, *render);
    scene.when = readRenderStep(file, *render);
  }
  if (const toml::table* camera = sectionTable(file, root, "camera"))
    scene.camera = readCamera(file, *camera);
  if (const toml::table* ambient = sectionTable(file, root, "ambient")) {
    const TomlTableReader reader(*ambient, "ambient", path, SceneTable::Ambient);
    if (auto intensity = reader.vector("intensity", Triple::Rgb, NumberRange::atLeast(0)))
      scene.ambient = toFloat(*intensity);
    scene.ambientSet = true;
  }
  if (const toml::table* environment = sectionTable(file, root, "environment"))
    scene.environment = readEnvironment(path, file.folder, *environment);
  const std::vector<const toml::table*> lights = tableArray(file, root, "light");
  for (std::size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(readLight(path, *lights[i], i));
  const std::vector<const toml::table*> clips = tableArray(file, root, "clip");
  for (std::size_t i = 0; i < clips.size(); ++i)
    scene.clips.push_back(readClip(file, *clips[i], fmt::format("clip[{}]", i), SceneTable::Clip));
  if (const toml::table* floor = sectionTable(file, root, "floor")) scene.floor = readFloor(file, *floor);
  scene.materials = readMaterials(file, root);
  if (const toml::table* materials = sectionTable(file, root, "material"))
    for (const auto& [name, value] : *materials)
      if (const auto* table = value.as_table(); table && table->contains("ka")) scene.ambientSet = true;
  const std::vector<const toml::table*> meshes = tableArray(file, root, "mesh");
  for (std::size_t i = 0; i < meshes.size(); ++i)
    scene.meshes.push_back(readMesh(file, *meshes[i], i, scene.materials));
  if (const toml::table* animation = sectionTable(file, root, "animation"))
    scene.animation = readAnimation(*animation, file.path, scene.lights.size());
  return scene;
}

SceneDescription loadScene(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError(SourceLocation{path},
                     fmt::format("cannot open '{}': it is a directory, not a scene file", path));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(SourceLocation{path}, fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw InputError(SourceLocation{path}, fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  return parseScene(text.str(), path);
}

}  // namespace lancer
