// The pieces of the _lancer extension module, one concept per file (mesh arrays, scenes and cameras,
// rendering, images, errors), and the Python-side scene they share.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <pybind11/pybind11.h>

#include <toml++/toml.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "lancer/image/color_map.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/up_axis.hpp"

namespace lancer::python {

namespace py = pybind11;

struct PythonVolume;  // lancer.Volume (volume_binding.cpp)

// What a Mesh keeps of its volume: the volume of a Mesh lancer.read_msh read, read from its file the
// first time a probe or a render draws inside it, then kept for the Mesh's later probes and renders
// and its quick looks' (a Mesh does not change once made); and the lancer.Volume its probes use, with
// its point locator, built once.
struct MeshVolume {
  std::mutex mutex;  // renders and probes release the GIL
  std::shared_ptr<const VolumeMesh> volume;
  std::shared_ptr<PythonVolume> probed;
};

// The MeshVolume of `mesh`, shared by its Python object and every Scene made from it, held as long
// as one of them lives (volume_binding.cpp). Call with the GIL held.
std::shared_ptr<MeshVolume> meshVolumeOf(const std::shared_ptr<const Mesh>& mesh);

// lancer.Scene: what a scene file or the quick look says, before any mesh is loaded. A quick look
// keeps its mesh (the Python Mesh it was made from), which every render reuses instead of a file,
// and what the mesh keeps of its volume (shared with the Mesh and the Scene's copies).
struct PythonScene {
  SceneDescription description;
  std::shared_ptr<const Mesh> quickLookMesh;
  std::shared_ptr<MeshVolume> quickLookVolume = std::make_shared<MeshVolume>();
  // A scene file's TOML, or one built in code (Scene(), add_mesh, ...): the scene loader reads it
  // again after each change (scene_building_binding.cpp). Null for a quick look. Shared by copies of
  // the Scene until one changes it (each change makes a new table).
  std::shared_ptr<const toml::table> document;
  std::string folder;  // relative paths in the document resolve against this
  // givenMeshes[i]: the lancer.Mesh that [[mesh]] i stands for, in memory, or null (read from its file).
  std::vector<std::shared_ptr<const Mesh>> givenMeshes;
  // givenVolumes[i]: what givenMeshes[i] keeps of its file's volume (meshVolumeOf), shared with its
  // Python Mesh; null for a mesh made with its volume or without a file.
  std::vector<std::shared_ptr<MeshVolume>> givenVolumes;
  // A Camera set in Python (scene.camera = ...), which the document's [camera] cannot say (a gmsh view).
  std::optional<CameraSettings> camera;
};

// The volume a render of `scene` with `overrides` draws from: none when it draws nothing inside
// (or for a scene file, whose meshes are read with their volumes when the scene is built); else the
// quick look's mesh's volume: the one it was made with, else the one read from the file
// lancer.read_msh read it from, once for the Mesh (volume_binding.cpp).
// An InputError for a mesh made from arrays or by gmsh, which has no volume elements.
std::shared_ptr<const VolumeMesh> quickLookVolumeFor(const PythonScene& scene,
                                                     const RenderOverrides& overrides, int threads);

// The volumes of the scene's meshes in memory (Scene.add_mesh) that a render with `overrides` draws
// inside, for RenderRequest::givenVolumes: the file's volume of a Mesh lancer.read_msh read, read once
// for the Mesh as for its quick look, where the [[mesh]] needs one (needsVolume); else null (a mesh
// made with its volume carries it). Call without the GIL.
std::vector<std::shared_ptr<const VolumeMesh>> givenVolumesFor(const PythonScene& scene,
                                                               const RenderOverrides& overrides, int threads);

// The quick look of a mesh, as `lancer render part.msh` makes it.
PythonScene quickLookOf(std::shared_ptr<const Mesh> mesh);
PythonScene quickLookOf(std::shared_ptr<const Mesh> mesh, std::optional<UpAxis> up);

// Scene.quick_look's keywords for results, each None when not given: color_by as a dict of the
// scene file's keys (a field's name is read apart, with color_map=, color_range=, component=),
// isolines and arrows (a field's name or a dict), legend ('right', 'bottom' or 'none').
struct ResultKeywords {
  std::optional<py::object> colorBy, isolines, arrows;
  std::optional<std::string> legend;
};
// Reads them into the instance through the scene loader's readers (result_arguments.cpp): a bad
// value is an InputError with the scene file's message, a bad type a TypeError.
void applyResultKeywords(MeshInstance& instance, const ResultKeywords& keywords);

// Keyword arguments as the TOML table of a scene file's section with those keys (str, numbers, bools,
// lists, tuples, dicts, numpy arrays and scalars; None leaves a key out): the scene loader then reads
// it as it reads a file. `name` ("add_mesh") names the call in a TypeError.
toml::table keywordTable(const py::dict& keys, const std::string& name);

// color_map=: a map's name, or a list of two or more colours (ValueError, TypeError otherwise).
ColorMap colorMapArgument(const py::object& map);

// A threads= argument: 0 (every core) to kMaxThreads, else a ValueError saying so.
void requireThreads(int threads);

// A lancer.LancerWarning through Python's warnings.warn (an error when the filters make it one).
// stackLevel as warnings.warn's: 1 the caller of the C++ function, 2 its caller (a lancer/*.py wrapper's).
void warnUser(const std::string& message, int stackLevel = 1);
void warnUser(const std::vector<std::string>& messages, int stackLevel = 1);

void bindErrors(py::module_& module);
void bindSceneBuilding(py::class_<PythonScene>& scene);
void bindMesh(py::module_& module);
void bindScene(py::module_& module);
void bindRender(py::module_& module);
void bindAnimate(py::module_& module);
void bindImage(py::module_& module);
void bindVolume(py::module_& module);
void bindListViews(py::module_& module);
void bindMemory(py::module_& module);

}  // namespace lancer::python
