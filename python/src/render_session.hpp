// What lancer.render and lancer.animate share: the keyword arguments as RenderOverrides, the scene
// built and its accelerator, and a render that Ctrl-C stops (Python's signal handlers run on the
// calling thread between tiles while the workers trace without the GIL).
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "lancer/accel/accelerator.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer::python {

// The keyword arguments of render and animate that override the scene's settings (None: the scene's).
struct RenderArguments {
  std::optional<int> width, height, samples, maxDepth;
  std::optional<std::string> shading, sampler, integrator, look;
  std::optional<double> noise;
  std::optional<bool> srgb, transparentBackground, edges;
  int threads = 0;
  bool progress = false;
};

// Checks the arguments' ranges and names (ValueError) and turns them into overrides.
RenderOverrides renderOverridesFromArguments(const RenderArguments& arguments);

// A lancer.Scene, or the quick look of a lancer.Mesh (TypeError for anything else).
PythonScene sceneOf(const py::object& target);

struct PreparedRender {
  SceneDescription description;
  Scene scene;
  Accelerator accelerator;
};

// Applies the overrides, checks the image's memory, loads the meshes and builds the accelerator
// (without the GIL, on `threads` threads, 0: every core); the meshes' warnings become Python UserWarnings.
PreparedRender prepareRender(PythonScene scene, const RenderOverrides& overrides, int threads);

// The two places that read Scene's fields, kept here so that a change to Scene's layout touches one file.
inline Accelerator buildSceneAccelerator(const Scene& scene, int threads) {
  KdBuildOptions options;
  options.threads = threads;
  return Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah, options);
}
inline const std::vector<std::string>& sceneWarnings(const Scene& scene) { return scene.warnings; }
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
