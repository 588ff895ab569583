// lancer.Volume (read_volume): the volume elements of a .msh file and the fields inside them, and
// Volume.probe, a field's values at points, interpolated in the element that holds each; and the
// volume a Mesh keeps, read once from its file, for its probes and its renders' slices, isosurfaces
// and field lines.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_probe.hpp"
#include "lancer/scene/results/volume_views.hpp"

namespace lancer::python {

// The volume and its point locator, built once.
struct PythonVolume {
  std::string path;
  std::shared_ptr<const VolumeMesh> volume;
  std::unique_ptr<VolumeLocator> locator;
};

namespace {

std::shared_ptr<PythonVolume> probeable(std::string path, std::shared_ptr<const VolumeMesh> volume) {
  auto result = std::make_shared<PythonVolume>();
  result->path = std::move(path);
  result->volume = std::move(volume);
  result->locator = std::make_unique<VolumeLocator>(*result->volume);
  return result;
}

std::shared_ptr<PythonVolume> readVolume(const std::string& path, int threads,
                                         const std::vector<std::string>& views) {
  requireThreads(threads);
  py::gil_scoped_release release;
  MeshWithVolume read = readMeshFileWithVolume(path, threads);
  addViewFiles(read, views);
  return probeable(path, std::move(read.volume));
}

// The volume under a Mesh lancer.read_msh read: its file's, with the views read_msh put on it, read
// the first time only. Called without the GIL.
std::shared_ptr<const VolumeMesh> fileVolumeOf(const Mesh& mesh, MeshVolume& kept, int threads) {
  const std::lock_guard<std::mutex> lock(kept.mutex);
  if (!kept.volume) {
    MeshWithVolume read = readMeshFileWithVolume(mesh.source.path, threads);
    addViewFiles(read, mesh.source.viewFiles);  // read_msh's views= inside the volume too
    // The volume must be the one under the Mesh's surface.
    if (read.mesh.faces.size() != mesh.faces.size() || read.mesh.positions.size() != mesh.positions.size())
      throw InputError(
          SourceLocation{mesh.source.path},
          fmt::format("the file has changed since lancer.read_msh read it ({} faces then, {} now): "
                      "read it again to draw or probe inside its volume",
                      mesh.faces.size(), read.mesh.faces.size()));
    kept.volume = std::move(read.volume);
  }
  return kept.volume;
}

// Mesh.volume: the volume it was made with (arrays), or its file's, read once; None for a mesh made
// without volume cells.
std::shared_ptr<PythonVolume> volumeOfMesh(const std::shared_ptr<Mesh>& mesh) {
  if (!mesh->volume && mesh->source.fileBytes == 0) return nullptr;
  const std::shared_ptr<MeshVolume> kept = meshVolumeOf(mesh);
  py::gil_scoped_release release;
  std::shared_ptr<const VolumeMesh> volume = mesh->volume ? mesh->volume : fileVolumeOf(*mesh, *kept, 0);
  const std::lock_guard<std::mutex> lock(kept->mutex);
  if (!kept->probed) kept->probed = probeable(mesh->source.path, std::move(volume));
  return kept->probed;
}

py::array_t<double> probe(const PythonVolume& volume, const py::object& points, const std::string& field,
                          std::optional<int> step) {
  const auto checked = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  if (!checked ||
      !((checked.ndim() == 2 && checked.shape(1) == 3) || (checked.ndim() == 1 && checked.shape(0) == 3)))
    throw py::value_error("points must be an (N, 3) array of x, y, z (or one point of 3 numbers)");
  const std::size_t count = checked.ndim() == 1 ? 1 : static_cast<std::size_t>(checked.shape(0));
  const double* xyz = checked.data();
  if (field.empty()) throw py::value_error("field must name one of the volume's fields (Volume.fields)");
  std::vector<float> values;
  int components = 0;
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < count; ++i) {
      const Vec3d point{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
      const ProbeResult result =
          probeVolume(*volume.volume, *volume.locator, point, field, step.value_or(0), volume.path);
      const std::vector<float>& v = result.values.front().values;
      components = static_cast<int>(v.size());
      values.insert(values.end(), v.begin(), v.end());
    }
  }
  py::array_t<double> out(std::vector<py::ssize_t>{static_cast<py::ssize_t>(count), components});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) data[i] = values[i];
  return out;
}

// Where the first of the overrides' volume views was asked for, for messages.
SourceLocation volumeKeyword(const RenderOverrides& overrides) {
  if (!overrides.slices.empty()) return overrides.slices.front().where;
  return SourceLocation{overrides.isosurfaces ? "isosurfaces" : "streamlines"};
}

}  // namespace

std::shared_ptr<const VolumeMesh> quickLookVolumeFor(const PythonScene& scene,
                                                     const RenderOverrides& overrides, int threads) {
  if (!scene.quickLookMesh) return nullptr;
  // The overrides on a copy of the description say what the render draws, as the scene's own keys do.
  SceneDescription applied = scene.description;
  applyRenderOverrides(applied, overrides, scene.quickLookMesh.get());
  const MeshInstance& instance = applied.meshes.front();
  if (!needsVolume(applied, instance)) return nullptr;
  const Mesh& mesh = *scene.quickLookMesh;
  if (mesh.volume) return mesh.volume;  // made from arrays with its volume cells
  if (mesh.source.fileBytes == 0) {
    // Made from arrays of faces or by gmsh: the faces are all there is. Coloured caps then stay
    // flat; field lines alone are traced across the faces when they are flat (a 2D model).
    if (!instance.volume.any()) return nullptr;
    if (instance.volume.slices.empty() && !instance.volume.isosurfaces)
      return std::make_shared<const VolumeMesh>();
    throw InputError(
        volumeKeyword(overrides),
        fmt::format("'{}' has no volume elements (tetrahedra, hexahedra, prisms, pyramids): a mesh "
                    "made from arrays without volume cells, or by gmsh, is its surface alone; give "
                    "lancer.Mesh its tetrahedra (cells={{'tetra': ...}}) or read the .msh file with "
                    "lancer.read_msh to draw slices, isosurfaces or field lines inside it",
                    mesh.source.path));
  }
  return fileVolumeOf(mesh, *scene.quickLookVolume, threads);
}

std::vector<std::shared_ptr<const VolumeMesh>> givenVolumesFor(const PythonScene& scene,
                                                               const RenderOverrides& overrides,
                                                               int threads) {
  std::vector<std::shared_ptr<const VolumeMesh>> volumes(scene.givenMeshes.size());
  if (std::all_of(scene.givenVolumes.begin(), scene.givenVolumes.end(),
                  [](const auto& kept) { return !kept; }))
    return volumes;
  // The overrides on a copy of the description say what the render draws, as the scene's own keys do.
  SceneDescription applied = scene.description;
  applyRenderOverrides(applied, overrides, nullptr);
  for (std::size_t i = 0; i < volumes.size() && i < scene.givenVolumes.size() && i < applied.meshes.size();
       ++i) {
    const std::shared_ptr<const Mesh>& mesh = scene.givenMeshes[i];
    if (mesh && scene.givenVolumes[i] && needsVolume(applied, applied.meshes[i]))
      volumes[i] = fileVolumeOf(*mesh, *scene.givenVolumes[i], threads);
  }
  return volumes;
}

std::shared_ptr<MeshVolume> meshVolumeOf(const std::shared_ptr<const Mesh>& mesh) {
  // By the mesh, weakly: every Python object and Scene of the same Mesh finds the one its holders
  // keep. A live entry's mesh is alive (each holder holds it too), so its address names it alone.
  static auto* const byMesh = new std::vector<std::pair<const Mesh*, std::weak_ptr<MeshVolume>>>();
  // By the Python object, strongly, for as long as it lives: a Mesh's probes between renders.
  // Both leaked on purpose: the interpreter may outlive the module's static destructors.
  static auto* const byObject = new py::object(py::module_::import("weakref").attr("WeakKeyDictionary")());
  std::erase_if(*byMesh, [](const auto& entry) { return entry.second.expired(); });
  std::shared_ptr<MeshVolume> kept;
  for (const auto& [owner, volume] : *byMesh)
    if (owner == mesh.get()) kept = volume.lock();
  if (!kept) {
    kept = std::make_shared<MeshVolume>();
    byMesh->emplace_back(mesh.get(), kept);
  }
  const py::object self = py::cast(std::const_pointer_cast<Mesh>(mesh));
  if (byObject->attr("get")(self).is_none())
    byObject->attr("__setitem__")(self, py::capsule(new std::shared_ptr<MeshVolume>(kept), [](void* held) {
                                    delete static_cast<std::shared_ptr<MeshVolume>*>(held);
                                  }));
  return kept;
}

void bindVolume(py::module_& module) {
  py::class_<PythonVolume, std::shared_ptr<PythonVolume>>(
      module, "Volume", "The volume elements of a .msh file and the fields inside them (read_volume)")
      .def_property_readonly(
          "cells", [](const PythonVolume& v) { return v.volume->cellCount(); },
          "the number of volume elements (tetrahedra, hexahedra, prisms, pyramids)")
      .def_property_readonly(
          "fields",
          [](const PythonVolume& v) {
            std::vector<std::string> names;
            for (const VolumeField& field : v.volume->fields)
              if (std::find(names.begin(), names.end(), field.name) == names.end())
                names.push_back(field.name);
            return names;
          },
          "the names of the fields given inside the volume")
      .def(
          "probe", &probe, py::arg("points"), py::arg("field"), py::arg("step") = py::none(),
          "the field's values at points ((N, 3) or one point), interpolated in the element that holds each: "
          "(N, components) float64, at step `step` (default 0). Raises InputError for a point in no element, "
          "a field or step the file does not have")
      .def("__repr__", [](const PythonVolume& v) {
        return fmt::format("<lancer.Volume '{}': {} cells, {} nodes>", v.path, v.volume->cellCount(),
                           v.volume->nodes.size());
      });
  module.def("read_volume", &readVolume, py::arg("path"), py::arg("threads") = 0,
             py::arg("views") = std::vector<std::string>{},
             "Reads the volume elements of a gmsh .msh file or a list-based .pos view and the fields inside "
             "them, for probes (threads: for the assembly, 0: every core; views: .pos files put on the "
             "volume, as read_msh's views=)");
  auto mesh = py::reinterpret_borrow<py::class_<Mesh, std::shared_ptr<Mesh>>>(module.attr("Mesh"));
  mesh.def_property_readonly(
          "volume", &volumeOfMesh,
          "the volume elements and the fields inside them (a lancer.Volume): those the mesh was made with "
          "from arrays, or those of the file it was read from (read once, then kept with the mesh); None for "
          "a "
          "mesh made without volume cells")
      .def(
          "probe",
          [](const std::shared_ptr<Mesh>& self, const py::object& points, const std::string& field,
             std::optional<int> step) {
            const std::shared_ptr<PythonVolume> volume = volumeOfMesh(self);
            if (!volume)
              throw InputError(SourceLocation{self->source.path},
                               "the mesh has no volume elements (tetrahedra, hexahedra, prisms, pyramids) "
                               "to probe inside: make it with its volume cells");
            return probe(*volume, points, field, step);
          },
          py::arg("points"), py::arg("field"), py::arg("step") = py::none(),
          "Mesh.volume.probe: the field's values at points ((N, 3) or one point), interpolated in the "
          "element that holds each, (N, components) float64");
}

}  // namespace lancer::python
