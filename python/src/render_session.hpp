// What lancer.render and lancer.animate share: the keyword arguments as RenderOverrides, the render
// prepared from them, and a render that Ctrl-C stops (Python's signal handlers run on the
// calling thread between tiles while the workers trace without the GIL).
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "lancer/image/legend.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer::python {

// The keyword arguments of render and animate that override the scene's settings (None: the scene's).
struct RenderArguments {
  std::optional<int> width, height, samples, maxDepth;
  std::optional<std::string> shading, sampler;
  std::optional<bool> srgb, transparentBackground, edges, denoise;
  std::optional<std::string> encoding, toneMap;  // "srgb" | "linear"; "none" | "filmic" | "aces"
  std::optional<double> exposure;
  std::optional<std::string> integrator, look;
  std::optional<double> noise, adaptiveNoise;
  int threads = 0;
  bool progress = false;
  // The command line's result options on every field-coloured mesh (--color-map, --range, --log,
  // --legend, --isolines, --bands), arrows of a vector field and cut planes (--arrows, --clip).
  py::object colorMap;  // a map's name or a list of colours
  std::optional<std::pair<double, double>> range;
  std::optional<bool> log;
  std::optional<std::string> scale;  // "linear" | "log"
  std::optional<std::string> legend;
  std::optional<int> isolines, bands;
  py::object arrows;  // a field's name or a dict of the scene keys
  py::object clip;    // a plane as text, or a list of them
  // Inside the volume (--slice, --skin, --isosurfaces, --streamlines): planes as text or dicts of a
  // [[mesh.slice]]'s keys; "FIELD", "FIELD:COUNT" or a dict of the scene keys.
  py::object slices, isosurfaces, streamlines;
  std::optional<std::string> skin;
};

// Checks render's and animate's result keywords and puts them into `overrides` (result_arguments.cpp).
void applyResultArguments(const RenderArguments& arguments, RenderOverrides& overrides);
// Their slices=, skin=, isosurfaces= and streamlines=, read as --slice, --skin, ... or as the scene
// file's keys (a dict), with the messages those get.
void applyVolumeArguments(const RenderArguments& arguments, RenderOverrides& overrides);

// Checks the arguments' ranges and names (ValueError) and turns them into overrides.
RenderOverrides renderOverridesFromArguments(const RenderArguments& arguments);

// A lancer.Scene, or the quick look of a lancer.Mesh (TypeError for anything else).
PythonScene sceneOf(const py::object& target);

// The library's prepareRender (render/render_preparation.hpp) of the scene with the overrides, run
// without the GIL on `threads` threads (0: every core); the meshes' warnings become Python UserWarnings.
// keepMeshes: for an animation over steps (RenderRequest::keepMeshes: the meshes kept, no accelerator).
PreparedRender prepareRender(PythonScene scene, const RenderOverrides& overrides, int threads,
                             bool keepMeshes = false);

// The two places that read Scene's fields, kept here so that a change to Scene's layout touches one file.
inline const std::vector<std::string>& sceneWarnings(const Scene& scene) { return scene.warnings; }

// The legends the scene asks for (color_by's `legend`, legend=), drawn into a rendered picture as
// `lancer render` and `lancer animate` draw them.
inline void drawSceneLegends(Image& image, const PreparedRender& prepared) {
  if (const std::optional<FieldColors>& fields = prepared.scene.fieldColors)
    drawLegends(image, fields->legends, fields->legendPlacement, prepared.description.render.srgb);
}
inline std::size_t sceneLightCount(const Scene& scene) { return scene.appearance.lights.size(); }

// Render options whose progress callback runs Python's signal handlers: a KeyboardInterrupt sets the
// cancel flag and is raised again by finish(), once the render has returned and the GIL is held.
class InterruptibleRender {
 public:
  InterruptibleRender(int threads, bool progress);
  InterruptibleRender(const InterruptibleRender&) = delete;
  InterruptibleRender& operator=(const InterruptibleRender&) = delete;
  // Raises the pending exception (KeyboardInterrupt) if a signal handler raised one.
  void finish();
  bool interrupted() const { return cancel_.load(); }

  RenderOptions options;

 private:
  std::atomic<bool> cancel_{false};
  std::unique_ptr<py::error_already_set> pending_;
  bool progress_ = false;
};

}  // namespace lancer::python
