// Preparing a render, the one path the CLI (`render`, `animate`) and the Python module share: the
// caller's settings over the scene's, the image's memory check, the scene, its accelerator and the camera.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/mesh/mesh.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/util/stage_times.hpp"

namespace lancer {

// How the caller holds the image while it renders: whole (animation frames, a GIF, a numpy array) or
// as the few bands of rows that Renderer::renderBands keeps (a still PNG, BMP or PPM streamed to its file).
enum class ImageBuffer { Whole, Bands };

// What a render is prepared from: the scene as described (a scene file's, or a mesh's quick look),
// before any mesh file is read, and what the caller puts over it.
struct RenderRequest {
  SceneDescription description;
  // The quick look's mesh, already read (the CLI read it to make the quick look; Python holds it):
  // used instead of a file, and its lights are placed again when the image size changes.
  std::optional<Mesh> quickLookMesh;
  // Its volume, read with it when the overrides draw slices, isosurfaces or coloured caps.
  std::shared_ptr<const VolumeMesh> quickLookVolume;
  // Meshes already in memory (Python's Scene.add_mesh): givenMeshes[i], when set, stands for
  // description.meshes[i] instead of its file (readSceneMeshes).
  std::vector<std::shared_ptr<const Mesh>> givenMeshes;
  // givenVolumes[i], when set: the volume of the file givenMeshes[i] was read from, for a mesh made
  // without one of its own (read once by the caller and kept with the mesh).
  std::vector<std::shared_ptr<const VolumeMesh>> givenVolumes;
  RenderOverrides overrides;
  AccelKind accel = kDefaultAccel;
  int threads = 0;  // of the scene preparation and the accelerator build; 0: every core
  // Asked once the overrides are applied, for the memory check; unset: the image is held whole.
  std::function<ImageBuffer(const RenderSettings&)> imageBuffer;
  // Called with the meshes as read, before the scene is built (gmsh's View[i] options need the
  // views' names); may change the description.
  std::function<void(SceneDescription&, const std::vector<Mesh>&)> withMeshes;
  // Keep the meshes as read (every step of their views) in PreparedRender::meshes: an animation
  // over steps builds each frame's scene and accelerator from them (render/step_animation.hpp), so
  // no accelerator is built here (PreparedRender::accelerator is empty). The scene is built with
  // the colour ranges the frames hold (holdStepColourRanges), so its legends are theirs.
  bool keepMeshes = false;
  // A scene of one mesh has its accelerator built alongside its orientation and normals
  // (scene/geometry_overlap.hpp): on two cores, -2% to +1.5% to the first ray, but the build's
  // buffers then live beside the mesh as read and the orientation's and normals' own, 40-50% more
  // peak memory (bench/RESULTS.md, "Time to first pixel"), so it is asked for.
  bool buildAlongside = false;
  // Stages the caller already spent on this render (the CLI's read of a bare mesh and its quick look's
  // setup), continued here and counted as load time.
  StageTimes stages;
};

// What a frame needs, held together (pbrt-v4's integrator holds its aggregate, lights and camera).
// A Renderer refers to the scene, accelerator and camera: keep the PreparedRender where it is while
// renderers made from it live.
struct PreparedRender {
  SceneDescription description;  // with the overrides applied
  Scene scene;                   // scene.warnings: the mesh readers' warnings, for the caller to show
  Accelerator accelerator;
  Camera camera;             // the description's camera for the settings' image size
  StageTimes stages;         // read, setup, renumber, orient, normals, scene, accel build
  double loadSeconds = 0;    // everything before the accelerator build
  double buildSeconds = 0;   // the accelerator build
  std::vector<Mesh> meshes;  // RenderRequest::keepMeshes: the meshes as read

  const RenderSettings& settings() const { return description.render; }
  Renderer renderer() const { return Renderer(scene, accelerator, camera, description.render); }
};

// The steps, in order: the overrides (applyRenderOverrides), the memory check (requireImageMemory),
// the scene (buildScene), its accelerator (buildAccelerator) and the camera (makeCamera). Throws
// InputError for bad settings, an image over the memory budget (at description.path), or a mesh that
// cannot be read. Prints nothing.
PreparedRender prepareRender(RenderRequest request);

// Frees the scene's geometry, per-face arrays and accelerator, keeping the description, camera,
// lights and legends: an animation over steps renders each frame from its own scene
// (StepScenes), so that one scene and one accelerator are held while the frames render.
void releaseSceneForSteps(PreparedRender& prepared);

// The bytes an image of the settings' size needs while it renders and is written: whole, the float
// image and its 8-bit copy; in bands, the bands renderBands keeps on `threads` workers, plus the
// writer's encoded row and its encoder's state, whatever the height.
std::uint64_t imageMemoryBytes(const RenderSettings& settings, int threads, ImageBuffer buffer);

// Throws InputError at `source` when imageMemoryBytes exceeds the memory budget (--max-memory).
void requireImageMemory(const RenderSettings& settings, int threads, ImageBuffer buffer,
                        const std::string& source);

// The accelerator over the scene's geometry, on `threads` threads (0: every core). Its own step, so
// that geometry that changes (a time step of a warped mesh) gets a new one without the rest.
Accelerator buildAccelerator(const Scene& scene, AccelKind kind, int threads);

}  // namespace lancer
