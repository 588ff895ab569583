// lancer.Volume (read_volume): the volume elements of a .msh file and the fields inside them, and
// Volume.probe, a field's values at points, interpolated in the element that holds each; and the
// volume a quick look's render draws slices, isosurfaces and field lines from.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/volume/volume_locator.hpp"
#include "lancer/mesh/volume/volume_probe.hpp"
#include "lancer/scene/results/volume_views.hpp"

namespace lancer::python {
namespace {

// The volume and its point locator, built once.
struct PythonVolume {
  std::string path;
  std::shared_ptr<const VolumeMesh> volume;
  std::unique_ptr<VolumeLocator> locator;
};

std::shared_ptr<PythonVolume> readVolume(const std::string& path, int threads) {
  requireThreads(threads);
  py::gil_scoped_release release;
  auto result = std::make_shared<PythonVolume>();
  result->path = path;
  result->volume = readMeshFileWithVolume(path, threads).volume;
  result->locator = std::make_unique<VolumeLocator>(*result->volume);
  return result;
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
  if (mesh.source.fileBytes == 0) {
    // Made from arrays or by gmsh: the faces are all there is. Coloured caps then stay flat; field
    // lines alone are traced across the faces when they are flat (a 2D model).
    if (!instance.volume.any()) return nullptr;
    if (instance.volume.slices.empty() && !instance.volume.isosurfaces)
      return std::make_shared<const VolumeMesh>();
    throw InputError(
        volumeKeyword(overrides),
        fmt::format("'{}' has no volume elements (tetrahedra, hexahedra, prisms, pyramids): a mesh "
                    "made from arrays or by gmsh is its surface alone; read the .msh file with "
                    "lancer.read_msh to draw slices, isosurfaces or field lines inside it",
                    mesh.source.path));
  }
  const std::lock_guard<std::mutex> lock(scene.quickLookVolume->mutex);
  if (!scene.quickLookVolume->volume) {
    MeshWithVolume read = readMeshFileWithVolume(mesh.source.path, threads);
    // The volume must be the one under the Mesh's surface.
    if (read.mesh.faces.size() != mesh.faces.size() || read.mesh.positions.size() != mesh.positions.size())
      throw InputError(
          SourceLocation{mesh.source.path},
          fmt::format("the file has changed since lancer.read_msh read it ({} faces then, {} now): "
                      "read it again to draw inside its volume",
                      mesh.faces.size(), read.mesh.faces.size()));
    scene.quickLookVolume->volume = std::move(read.volume);
  }
  return scene.quickLookVolume->volume;
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
             "Reads the volume elements of a gmsh .msh file and the fields inside them, for probes "
             "(threads: for the assembly, 0: every core)");
}

}  // namespace lancer::python
