// lancer.Scene (a scene file as `lancer render` reads it, or the quick look of a mesh) and
// lancer.Camera (the scene file's [camera] keys).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include "bindings.hpp"
#include "render_session.hpp"

#include "lancer/image/color_map.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/gmsh_view.hpp"
#include "lancer/scene/scene_loader.hpp"

namespace lancer::python {
namespace {

using Triple = std::array<double, 3>;

Vec3d toVec(const Triple& t) { return {t[0], t[1], t[2]}; }
Triple toTriple(const Vec3d& v) { return {v.x, v.y, v.z}; }

std::optional<UpAxis> upAxisArgument(const std::optional<std::string>& up) {
  if (!up) return std::nullopt;
  const std::optional<UpAxis> axis = parseUpAxis(*up);
  if (!axis) throw py::value_error(fmt::format("up='{}' is not an axis: use x, y, z, -x, -y or -z", *up));
  return axis;
}

Projection projectionArgument(const std::string& name) {
  const auto projection = enumFromName<Projection>(kProjectionNames, name);
  if (!projection)
    throw py::value_error(fmt::format("projection='{}': use 'perspective' or 'orthographic'", name));
  return *projection;
}

CameraSettings makeCameraSettings(const std::optional<Triple>& position, const std::optional<Triple>& lookAt,
                                  const Triple& up, double fov, const std::string& projection,
                                  const std::optional<double>& viewHeight) {
  CameraSettings camera;
  camera.viewChosen = true;  // a Camera the caller made: a flat model is not turned straight on
  if (position) camera.position = toVec(*position);
  if (lookAt) camera.lookAt = toVec(*lookAt);
  camera.up = toVec(up);
  if (!(fov > 0 && fov < 180))
    throw py::value_error(fmt::format("fov={} degrees: use a value in (0, 180)", fov));
  camera.fovDegrees = fov;
  camera.projection = projectionArgument(projection);
  if (viewHeight && !(*viewHeight > 0))
    throw py::value_error(fmt::format("view_height={}: use a positive height in world units", *viewHeight));
  camera.viewHeight = viewHeight;
  if (camera.position && camera.lookAt && *camera.position == *camera.lookAt)
    throw py::value_error("position and look_at are the same point: the camera would look nowhere");
  if (!(dot(camera.up, camera.up) > 0))
    throw py::value_error("up is the zero vector: give the screen's up direction");
  return camera;
}

std::string describeCamera(const CameraSettings& camera) {
  if (camera.gmshView) return fmt::format("lancer.Camera.from_gmsh_file('{}')", camera.gmshView->source);
  auto vec = [](const std::optional<Vec3d>& v) {
    return v ? fmt::format("({:g}, {:g}, {:g})", v->x, v->y, v->z) : std::string("None");
  };
  return fmt::format(
      "lancer.Camera(position={}, look_at={}, up=({:g}, {:g}, {:g}), fov={:g}, projection='{}', "
      "view_height={})",
      vec(camera.position), vec(camera.lookAt), camera.up.x, camera.up.y, camera.up.z, camera.fovDegrees,
      kProjectionNames[static_cast<int>(camera.projection)],
      camera.viewHeight ? fmt::format("{:g}", *camera.viewHeight) : "None");
}

// color_by= of Scene.quick_look: the mesh coloured by one of its fields, as a scene file's
// `color_by = {field, map, range, step}` does. The field's name is checked when the scene is built
// (an InputError naming the fields the mesh has).
ColorBy colorByArgument(const std::string& field, const py::object& map,
                        const std::optional<std::pair<double, double>>& range, const std::string& component) {
  ColorBy colorBy;
  colorBy.field = field;
  colorBy.where = SourceLocation{"color_by"};
  const std::optional<FieldComponent> parsed = parseFieldComponent(component);
  if (!parsed)
    throw py::value_error(
        fmt::format("component='{}': use 'magnitude', 'x', 'y', 'z', '0' to '8' or 'von_mises'", component));
  colorBy.component = *parsed;
  colorBy.map = colorMapArgument(map);
  if (range && !(std::isfinite(range->first) && std::isfinite(range->second) && range->first < range->second))
    throw py::value_error(fmt::format("color_range=({:g}, {:g}): give (low, high), finite, low < high",
                                      range->first, range->second));
  colorBy.range = range;
  return colorBy;
}

// warp= of Scene.quick_look: "displacement" or ("displacement", factor).
WarpSettings warpArgument(const py::object& warp) {
  WarpSettings settings;
  settings.where = SourceLocation{"warp"};
  if (py::isinstance<py::str>(warp)) {
    settings.field = warp.cast<std::string>();
  } else if (py::isinstance<py::tuple>(warp) && py::len(warp) == 2) {
    const auto pair = warp.cast<py::tuple>();
    settings.field = pair[0].cast<std::string>();
    settings.factor = pair[1].cast<double>();
  } else {
    throw py::type_error("warp= takes a field name or (field name, factor), e.g. ('displacement', 2.0)");
  }
  if (settings.field.empty() || !std::isfinite(settings.factor))
    throw py::value_error("warp=: give a field's name and a finite factor, e.g. ('displacement', 2.0)");
  return settings;
}

}  // namespace

PythonScene quickLookOf(std::shared_ptr<const Mesh> mesh, std::optional<UpAxis> up) {
  if (const std::string reason = nothingToDrawReason(*mesh); !reason.empty())
    throw InputError(SourceLocation{mesh->source.path}, "nothing to draw: " + reason);
  PythonScene scene;
  scene.description = quickLookScene(mesh->source.path, *mesh, up);
  scene.quickLookVolume = meshVolumeOf(mesh);
  scene.quickLookMesh = std::move(mesh);
  return scene;
}

PythonScene quickLookOf(std::shared_ptr<const Mesh> mesh) {
  return quickLookOf(std::move(mesh), std::nullopt);
}

void bindScene(py::module_& module) {
  module.def(
      "color_map",
      [](const py::object& map, int n) {
        if (n < 2 || n > 65536) throw py::value_error(fmt::format("n={}: give 2 to 65536 samples", n));
        const ColorMap colors = colorMapArgument(map);
        py::array_t<float> array({static_cast<py::ssize_t>(n), py::ssize_t{3}});
        auto out = array.mutable_unchecked<2>();
        for (int i = 0; i < n; ++i) {
          const Vec3 c = colors(static_cast<float>(i) / static_cast<float>(n - 1));
          out(i, 0) = c.x;
          out(i, 1) = c.y;
          out(i, 2) = c.z;
        }
        return array;
      },
      py::arg("map"), py::arg("n") = 256,
      "The colours a map gives at n values evenly spaced from its low end to its high end, as an (n, 3) "
      "float32 array of display values in [0, 1] (matplotlib's cmap(np.linspace(0, 1, n))[:, :3]); map as "
      "Scene.quick_look's color_map");
  module.def(
      "color_maps",
      [] {
        const std::vector<std::string_view> names = colorMapNames();
        return std::vector<std::string>(names.begin(), names.end());
      },
      "The names of the colour maps (each also with '_r', reversed): matplotlib's, then gmsh:0 to gmsh:24");

  py::class_<CameraSettings>(module, "Camera",
                             "Where the camera is and how it projects; None: framed automatically")
      .def(py::init(&makeCameraSettings), py::kw_only(), py::arg("position") = py::none(),
           py::arg("look_at") = py::none(), py::arg("up") = Triple{0, 1, 0}, py::arg("fov") = 40.0,
           py::arg("projection") = "perspective", py::arg("view_height") = py::none())
      .def_property_readonly("position",
                             [](const CameraSettings& c) {
                               return c.position ? std::optional<Triple>(toTriple(*c.position))
                                                 : std::nullopt;
                             })
      .def_property_readonly("look_at",
                             [](const CameraSettings& c) {
                               return c.lookAt ? std::optional<Triple>(toTriple(*c.lookAt)) : std::nullopt;
                             })
      .def_property_readonly("up", [](const CameraSettings& c) { return toTriple(c.up); })
      .def_property_readonly("fov", [](const CameraSettings& c) { return c.fovDegrees; })
      .def_property_readonly("projection",
                             [](const CameraSettings& c) {
                               return std::string(kProjectionNames[static_cast<int>(c.projection)]);
                             })
      .def_property_readonly("view_height", [](const CameraSettings& c) { return c.viewHeight; })
      .def_property_readonly(
          "gmsh_view", [](const CameraSettings& c) { return c.gmshView.has_value(); },
          "True for a camera that reproduces a gmsh view (from_gmsh, from_gmsh_file)")
      .def_static(
          "from_gmsh_file",
          [](const std::string& path) {
            CameraSettings camera;
            camera.gmshView = readGmshView(path);
            return camera;
          },
          py::arg("path"), "The view of a gmsh options file (File > Save Model Options writes part.msh.opt)")
      .def("__repr__", &describeCamera);
  module.def(
      "_camera_from_gmsh_options",
      [](const std::map<std::string, double>& options) {
        CameraSettings camera;
        camera.gmshView = gmshViewFromOptions(
            [&](const std::string& name) -> std::optional<double> {
              const auto found = options.find(name);
              return found == options.end() ? std::nullopt : std::optional<double>(found->second);
            },
            "gmsh");
        return camera;
      },
      py::arg("options"));

  py::class_<PythonScene> sceneClass(
      module, "Scene",
      "A scene: a scene file, one built in code (Scene(), add_mesh, ...), or the quick "
      "look of a mesh");
  bindSceneBuilding(sceneClass);
  sceneClass
      .def_static(
          "load",
          [](const std::string& path) {
            py::gil_scoped_release release;
            PythonScene scene;
            scene.description = loadScene(path);
            // Kept for add_mesh and the like; the loader has read the file, so it parses.
            scene.document = std::make_shared<const toml::table>(toml::parse_file(path));
            scene.folder = std::filesystem::path(path).parent_path().string();
            return scene;
          },
          py::arg("path"), "Reads a scene file (.toml) exactly as `lancer render` does")
      .def_static(
          "quick_look",
          [](std::shared_ptr<const Mesh> mesh, const std::optional<std::string>& up,
             const py::object& colorBy, const py::object& colorMap,
             const std::optional<std::pair<double, double>>& colorRange, const std::optional<int>& step,
             const py::object& warp, const std::string& component, const std::string& undeformed,
             const py::object& isolines, const py::object& arrows, const std::optional<std::string>& legend,
             const std::optional<int>& bands, const std::optional<bool>& log,
             const std::optional<std::string>& scale) {
            if (step && *step < 0)
              throw py::value_error(fmt::format("step={}: a field's steps count from 0", *step));
            if (undeformed != "none" && undeformed != "edges" && undeformed != "ghost")
              throw py::value_error(
                  fmt::format("undeformed='{}': use 'none', 'edges' or 'ghost'", undeformed));
            PythonScene scene = quickLookOf(std::move(mesh), upAxisArgument(up));
            MeshInstance& instance = scene.description.meshes.front();
            if (py::isinstance<py::str>(colorBy)) {
              instance.colorBy =
                  colorByArgument(colorBy.cast<std::string>(), colorMap, colorRange, component);
            } else if (!colorBy.is_none()) {
              if (!py::isinstance<py::dict>(colorBy))
                throw py::type_error(
                    "color_by= takes a field's name or a dict of the scene file's color_by keys, "
                    "e.g. {'field': 'stress', 'title': 'von Mises stress', 'units': 'MPa'}");
              const bool mapGiven =
                  !py::isinstance<py::str>(colorMap) || colorMap.cast<std::string>() != "viridis";
              if (mapGiven || colorRange || component != "magnitude")
                throw py::value_error(
                    "color_by as a dict holds its own 'map', 'range' and 'component': put them "
                    "in it instead of color_map=, color_range=, component=");
            }
            ResultKeywords keywords;
            if (py::isinstance<py::dict>(colorBy)) keywords.colorBy = colorBy;
            keywords.isolines = isolines;
            keywords.arrows = arrows;
            keywords.legend = legend;
            applyResultKeywords(instance, keywords);
            // bands= and log= (or scale=) as render() takes them: its checks and its messages.
            RenderArguments results;
            results.bands = bands;
            results.log = log;
            results.scale = scale;
            RenderOverrides overrides;
            applyResultArguments(results, overrides);
            applyRenderOverrides(scene.description, overrides, scene.quickLookMesh.get());
            if (!warp.is_none()) {
              instance.warp = warpArgument(warp);
              instance.undeformed = undeformed == "edges"   ? UndeformedStyle::Edges
                                    : undeformed == "ghost" ? UndeformedStyle::Ghost
                                                            : UndeformedStyle::None;
            }
            if (step) scene.description.when = StepSelection{step, std::nullopt, "step="};
            return scene;
          },
          py::arg("mesh"), py::arg("up") = py::none(), py::kw_only(), py::arg("color_by") = py::none(),
          py::arg("color_map") = "viridis", py::arg("color_range") = py::none(), py::arg("step") = py::none(),
          py::arg("warp") = py::none(), py::arg("component") = "magnitude", py::arg("undeformed") = "none",
          py::arg("isolines") = py::none(), py::arg("arrows") = py::none(), py::arg("legend") = py::none(),
          py::arg("bands") = py::none(), py::arg("log") = py::none(), py::arg("scale") = py::none(),
          "The scene `lancer render part.msh` makes of a bare mesh (up: 'x', 'y', 'z', '-x', ...; None: "
          "guessed); color_by names one of mesh.fields to colour it by, as a scene file's color_by "
          "(color_map a matplotlib map's name ('viridis', 'turbo', 'RdBu', 'jet', ...; lancer.color_maps() "
          "lists "
          "them), with '_r' reversed, 'gmsh:N' for gmsh's View.ColormapNumber N, or a list of colours such "
          "as "
          "['#000080', 'white', '#800000']; color_range (low, high), default the "
          "field's range over every step; component 'magnitude', 'x', 'y', 'z', '0'-'8' or 'von_mises'); "
          "warp 'displacement' or ('displacement', factor) draws the shape moved by that node vector "
          "(undeformed 'edges' or 'ghost' shows the shape before); step: the time step shown (default "
          "the first). color_by may also be a dict of the scene file's color_by keys ({'field': 'stress', "
          "'component': 'von_mises', 'title': 'von Mises stress', 'units': 'MPa', 'bands': 8}); isolines "
          "and arrows a field's name or a dict of their scene keys ({'field': 'T', 'count': 12, 'color': "
          "[0, 0, 0], 'width': 1.5}, {'field': 'velocity', 'max_count': 300}); legend 'right', 'bottom' "
          "or 'none' draws the colours' legend into the picture; bands=N shows the colours in N flat bands "
          "and log=True (or scale='log') maps them on a logarithmic scale, as render()'s bands= and log=")
      .def_property(
          "camera", [](const PythonScene& scene) { return scene.description.camera; },
          [](PythonScene& scene, const CameraSettings& camera) {
            scene.description.camera = camera;
            if (scene.document) scene.camera = camera;  // over the document's [camera], after any change
            // The quick look's key and fill follow its camera, wherever it is put.
            if (scene.quickLookMesh) placeQuickLookLights(scene.description, *scene.quickLookMesh);
          })
      .def_property_readonly("path", [](const PythonScene& scene) { return scene.description.path; })
      .def_property_readonly("width", [](const PythonScene& scene) { return scene.description.render.width; })
      .def_property_readonly("height",
                             [](const PythonScene& scene) { return scene.description.render.height; })
      .def_property_readonly(
          "mesh", [](const PythonScene& scene) { return scene.quickLookMesh; },
          "The quick look's mesh; None for a scene file")
      .def("__repr__", [](const PythonScene& scene) {
        return fmt::format("<lancer.Scene '{}': {} mesh{}, {} light{}, {}x{}>", scene.description.path,
                           scene.description.meshes.size(), scene.description.meshes.size() == 1 ? "" : "es",
                           scene.description.lights.size(), scene.description.lights.size() == 1 ? "" : "s",
                           scene.description.render.width, scene.description.render.height);
      });
}

}  // namespace lancer::python
