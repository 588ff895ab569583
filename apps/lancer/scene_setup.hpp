// What `render` and `animate` share: command-line overrides of the scene's render settings, loading
// a scene file or a bare mesh, building the accelerator once, Ctrl-C handling and progress lines.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "lancer/accel/accelerator.hpp"
#include "lancer/image/animation_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer::cli {

struct SceneOverrides {
  std::optional<int> width, height, samples, maxDepth;
  std::string shading;
  std::string sampler;
  std::string accel = "kdtree-sah";
  int threads = 0;
  bool srgb = false;
  bool edges = false;  // draw element edges on every mesh that does not set its own
  std::string up;      // --up: the automatic camera's up axis (x, y, z, -x, -y, -z)
  // --gmsh-view [FILE]: the camera of a gmsh options file; "" for the mesh's own MESH.msh.opt.
  std::optional<std::string> gmshView;
  bool quiet = false;
  bool timings = false;         // --timings: the preparation's stages on stderr
  std::string integrator;       // --integrator whitted|path|ao
  std::optional<double> noise;  // --noise: adaptive stop, in (0, 1)
  std::string look;             // --look studio|sky|sun
};

void addSceneOverrideOptions(CLI::App& command, SceneOverrides& overrides);

struct PreparedScene {
  SceneDescription description;
  Scene scene;
  Accelerator accelerator;
  double loadSeconds = 0;
  double buildSeconds = 0;
  StageTimes stages;  // read, orient, normals, scene, kd build: where loadSeconds + buildSeconds went
};

// "timings: read 0.052 s, orient 0.081 s, ..." (--timings).
std::string formatStageTimes(const StageTimes& stages);

// How a command holds the image while it renders: whole (animation frames, GIF) or as the few bands
// of rows that renderBands keeps (a still PNG, BMP or PPM streamed to its file).
enum class ImageBuffer { Whole, Bands };
// Asked once the overrides are applied, before any mesh is loaded, for the memory check.
using ImageBufferChoice = std::function<ImageBuffer(const RenderSettings&)>;

// Reads a scene file (.toml) or builds the quick-look scene of a mesh (.msh), applies the
// overrides, checks the image's memory against the budget (--max-memory), loads the meshes and builds
// the accelerator. Without a choice the image is held whole.
PreparedScene prepareScene(const std::string& input, const SceneOverrides& overrides,
                           const ImageBufferChoice& imageBuffer = {});

// Ctrl-C and SIGTERM set the flag instead of killing the process, so outputs stay untouched.
const std::atomic<bool>& installInterruptHandler();

// True when progress lines should go to stderr (a terminal, and not --quiet).
bool showProgress(const SceneOverrides& overrides);

// How the settings want images written: the sRGB curve or linear, alpha with a transparent background.
ImageWriteOptions imageWriteOptions(const RenderSettings& settings);

// A command's render options: its --threads, and Ctrl-C (or SIGTERM) stops the render.
RenderOptions commandRenderOptions(const SceneOverrides& overrides);

// Prints that the command was interrupted and `output` not written (it is left as it was), and
// returns the exit code for it.
int interruptedExit(const std::string& output);
// --loop, --dither and --palette, which `animate` and `assemble` share (their defaults are the writer's).
void addAnimationWriterOptions(CLI::App& command, AnimationOutputOptions& writer);
// Whether SIGINT or SIGTERM arrived. The handler removes the temporary files at once, so a write
// that fails afterwards failed because of the interrupt, and main reports the interrupt instead.
bool interruptRequested();

}  // namespace lancer::cli
