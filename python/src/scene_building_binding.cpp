// A lancer.Scene built in code (Scene(), add_mesh, add_light, add_material, add_clip, set) or
// parsed from a string (Scene.loads). The scene is kept as the TOML document a scene file would
// hold, each keyword argument the key of that name, and every change is read again by the scene
// loader (sceneFromToml): a Python scene has every key of a file, with the same checks and the same
// messages, naming the call ("add_mesh: error: mesh[0].color_by.map ...") instead of a file's line.
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>

#include "bindings.hpp"
#include "lancer/scene/scene_from_toml.hpp"
#include "lancer/scene/suggest.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer::python {
namespace {

// The single tables of a scene file that Scene.set fills.
constexpr std::array<std::string_view, 6> kSettableTables = {"render",      "camera", "ambient",
                                                             "environment", "floor",  "animation"};

std::string currentFolder() { return std::filesystem::current_path().string(); }

// The description the document says, read by the scene loader with messages naming `where`.
SceneDescription describe(const toml::table& document, const std::string& where, const PythonScene& scene) {
  SceneDescription description = sceneFromToml(document, where, scene.folder);
  if (scene.camera) description.camera = *scene.camera;
  return description;
}

// The scene with `document` in place of its own, once the loader has accepted it: checked with
// messages naming the call, then kept with messages naming the scene (its file, "<string>" or
// "Scene") for what a render finds later.
void commit(PythonScene& scene, toml::table document, const std::string& call) {
  describe(document, call, scene);  // throws InputError naming the call; nothing changes then
  scene.description = describe(document, scene.description.path, scene);
  scene.document = std::make_shared<const toml::table>(std::move(document));
}

toml::table& requireDocument(PythonScene& scene, toml::table& copy, const char* call) {
  if (!scene.document)
    throw py::value_error(
        fmt::format("{}: a quick look is the scene of one mesh and cannot change; build lancer.Scene() and "
                    "add_mesh(mesh, ...) for a scene of your own",
                    call));
  copy = *scene.document;
  return copy;
}

// The array of tables `key` ([[mesh]], [[light]], [[clip]]) of the document, made when absent.
toml::array& tableArray(toml::table& document, std::string_view key) {
  if (!document.contains(key)) document.insert(key, toml::array{});
  toml::array* array = document.get(key)->as_array();
  if (!array) throw py::value_error(fmt::format("the scene's {} is not an array of tables", key));
  return *array;
}

std::string absolutePath(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

void addMesh(PythonScene& scene, const py::object& mesh, const py::kwargs& keys) {
  toml::table document;
  requireDocument(scene, document, "add_mesh");
  if (keys.contains("file"))
    throw py::type_error(
        "add_mesh: give the mesh (a lancer.Mesh or a file's path) as the first argument, not file=");
  const std::size_t index = document.contains("mesh") ? tableArray(document, "mesh").size() : 0;
  py::dict rest;
  py::object material = py::none();
  for (const auto& [key, value] : keys) {
    if (key.cast<std::string>() == "material")
      material = py::reinterpret_borrow<py::object>(value);
    else
      rest[key] = value;
  }
  toml::table table = keywordTable(rest, "add_mesh");
  // views: .pos files, from the current folder (the document's folder is a scene file's).
  if (toml::array* views = table.get_as<toml::array>("views"))
    for (toml::node& view : *views)
      if (toml::value<std::string>* text = view.as_string()) *text = absolutePath(text->get());
  std::shared_ptr<const Mesh> given;
  if (py::isinstance<Mesh>(mesh)) {
    given = mesh.cast<std::shared_ptr<const Mesh>>();
    table.insert_or_assign("file", given->source.path.empty() ? std::string("<arrays>") : given->source.path);
  } else if (py::isinstance<py::str>(mesh) || py::hasattr(mesh, "__fspath__")) {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(mesh)).cast<std::string>();
    table.insert_or_assign("file", path.empty() ? path : absolutePath(path));
  } else {
    throw py::type_error(fmt::format("add_mesh takes a lancer.Mesh or a mesh file's path, not {}",
                                     py::repr(py::type::of(mesh)).cast<std::string>()));
  }
  if (py::isinstance<py::dict>(material)) {
    // A material of its own: defined under the mesh's name in messages, as a file would define it.
    const std::string name = fmt::format("mesh[{}]", index);
    if (!document.contains("material")) document.insert("material", toml::table{});
    toml::table* materials = document.get_as<toml::table>("material");
    if (!materials) throw py::value_error("the scene's material is not a table of materials");
    materials->insert_or_assign(name, keywordTable(material.cast<py::dict>(), "add_mesh(material"));
    table.insert_or_assign("material", name);
  } else if (py::isinstance<py::str>(material)) {
    table.insert_or_assign("material", material.cast<std::string>());
  } else if (!material.is_none()) {
    throw py::type_error(
        "add_mesh: material= takes a material's name (add_material) or a dict of material keys, e.g. "
        "{'kd': [0.8, 0.2, 0.2], 'shininess': 64}");
  }
  tableArray(document, "mesh").push_back(std::move(table));
  std::vector<std::shared_ptr<const Mesh>> givenMeshes = scene.givenMeshes;
  givenMeshes.resize(index);
  givenMeshes.push_back(given);
  // A Mesh lancer.read_msh read draws inside its file's volume as the file's path does: the volume
  // it keeps, read the first time a render needs it (givenVolumesFor).
  std::vector<std::shared_ptr<MeshVolume>> givenVolumes = scene.givenVolumes;
  givenVolumes.resize(index);
  givenVolumes.push_back(given && !given->volume && given->source.fileBytes > 0 ? meshVolumeOf(given)
                                                                                : nullptr);
  commit(scene, std::move(document), "add_mesh");
  scene.givenMeshes = std::move(givenMeshes);
  scene.givenVolumes = std::move(givenVolumes);
}

void addToArray(PythonScene& scene, const char* key, const char* call, const py::kwargs& keys) {
  toml::table document;
  requireDocument(scene, document, call);
  tableArray(document, key).push_back(keywordTable(keys, call));
  commit(scene, std::move(document), call);
}

void addMaterial(PythonScene& scene, const std::string& name, const py::kwargs& keys) {
  toml::table document;
  requireDocument(scene, document, "add_material");
  if (name.empty()) throw py::value_error("add_material: give the material a name");
  if (!document.contains("material")) document.insert("material", toml::table{});
  toml::table* materials = document.get_as<toml::table>("material");
  if (!materials) throw py::value_error("the scene's material is not a table of materials");
  materials->insert_or_assign(name, keywordTable(keys, "add_material"));
  commit(scene, std::move(document), "add_material");
}

// Scene.set("render", width=800, samples=4): keys of one of the single tables; None removes a key.
void setTable(PythonScene& scene, const std::string& name, const py::kwargs& keys) {
  toml::table document;
  requireDocument(scene, document, "set");
  if (std::find(kSettableTables.begin(), kSettableTables.end(), name) == kSettableTables.end()) {
    std::string names;
    for (const std::string_view table : kSettableTables)
      names += fmt::format("{}'{}'", names.empty() ? "" : ", ", table);
    throw py::value_error(
        fmt::format("set('{}', ...): the tables are {}{}", name, names, didYouMean(name, kSettableTables)));
  }
  if (!document.contains(name)) document.insert(name, toml::table{});
  toml::table* table = document.get_as<toml::table>(name);
  if (!table) throw py::value_error(fmt::format("the scene's {} is not a table", name));
  for (const auto& [key, value] : keys)
    if (value.is_none()) table->erase(key.cast<std::string>());
  for (auto&& [key, value] : keywordTable(keys, "set")) table->insert_or_assign(key, std::move(value));
  // The [camera] keys say the camera again: a Camera set before gives way to them.
  std::optional<CameraSettings> camera = scene.camera;
  if (name == "camera") scene.camera.reset();
  try {
    commit(scene, std::move(document), "set");
  } catch (...) {
    scene.camera = std::move(camera);
    throw;
  }
}

}  // namespace

PythonScene emptyScene() {
  PythonScene scene;
  scene.folder = currentFolder();
  scene.description.path = "Scene";
  commit(scene, toml::table{}, "Scene");
  return scene;
}

PythonScene sceneFromText(const std::string& text) {
  PythonScene scene;
  scene.folder = currentFolder();
  const std::string path = "<string>";
  toml::table document;
  try {
    document = toml::parse(text, std::string_view(path));
  } catch (const toml::parse_error& error) {
    throw InputError(locate(path, error.source()), std::string(error.description()));
  }
  scene.description = sceneFromToml(document, path, scene.folder);
  scene.document = std::make_shared<const toml::table>(std::move(document));
  return scene;
}

void bindSceneBuilding(py::class_<PythonScene>& scene) {
  scene
      .def(py::init(&emptyScene),
           "An empty scene, to fill with add_mesh, add_light, add_material, add_clip, set")
      .def_static("loads", &sceneFromText, py::arg("text"),
                  "A scene from the text of a scene file (TOML), as Scene.load reads a file: errors name "
                  "'<string>' and the line; relative paths are relative to the current folder")
      .def("add_mesh", &addMesh, py::arg("mesh"),
           "Adds a [[mesh]]: a lancer.Mesh (kept in memory) or a mesh file's path, with the [[mesh]] keys "
           "of a scene file as keyword arguments (material as a name or a dict of material keys, color_by, "
           "warp, isolines, arrows, edges, groups, translate, rotate, scale, clip=[{...}], slice=[{...}], "
           "...); checked by the scene loader as a file's keys are")
      .def(
          "add_light",
          [](PythonScene& s, const py::kwargs& keys) { addToArray(s, "light", "add_light", keys); },
          "Adds a [[light]] with the scene file's keys (type='point', position=[x, y, z], intensity=..., "
          "...)")
      .def(
          "add_clip", [](PythonScene& s, const py::kwargs& keys) { addToArray(s, "clip", "add_clip", keys); },
          "Adds a [[clip]] plane (point=[x, y, z], normal=[x, y, z], cap=True) that cuts every mesh")
      .def("add_material", &addMaterial, py::arg("name"),
           "Defines [material.NAME] with the scene file's material keys (kd, ks, shininess, reflectivity, "
           "...)")
      .def("set", &setTable, py::arg("table"),
           "Sets keys of one of the scene file's tables 'render', 'camera', 'ambient', 'environment', "
           "'floor', 'animation' (None removes a key), e.g. scene.set('render', width=800, samples=4)")
      .def(
          "to_toml",
          [](const PythonScene& s) {
            if (!s.document) throw py::value_error("to_toml: a quick look has no scene file");
            std::ostringstream text;
            text << toml::toml_formatter(*s.document);
            return text.str();
          },
          "The scene as scene-file text (a mesh kept in memory appears under its name)");
}

}  // namespace lancer::python
