// What `render` and `animate` share: command-line overrides of the scene's render settings, loading
// a scene file or a bare mesh into one render preparation, Ctrl-C handling and progress lines.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lancer/accel/accelerator.hpp"
#include "lancer/image/animation_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer::cli {

struct SceneOverrides {
  std::optional<int> width, height, samples, maxDepth;
  std::string shading;
  std::string sampler;
  std::string accel{kDefaultAccelName};
  int threads = 0;
  bool srgb = false;    // --srgb: the default encoding, over a scene's encoding = "linear"
  bool linear = false;  // --linear: the raw values (round(255 * I))
  std::string toneMap;  // --tonemap none | filmic | aces
  std::optional<double> exposure;
  std::optional<int> bitDepth;
  std::optional<int> quality;  // --quality Q: JPEG and lossy WebP, 1 to 100
  bool lossless = false;       // --lossless: WebP without loss
  std::optional<double> dpi;   // --dpi N: the resolution the picture's file records
  bool denoise = false;
  bool edges = false;  // draw element edges on every mesh that does not set its own
  std::string up;      // --up: the automatic camera's up axis (x, y, z, -x, -y, -z)
  // --view iso|front|...: the automatic camera's side; --azimuth, --elevation (degrees) turn the camera
  // about its target from there, --zoom brings it closer (view_presets.hpp).
  std::string view;
  std::optional<double> azimuth, elevation, zoom;
  std::string background;    // --background COLOR: a CSS name, #rrggbb, #rgb or r,g,b in 0..1
  bool transparent = false;  // --transparent: the background's alpha 0 (PNG, EXR, GIF)
  // --gmsh-view [FILE]: the camera of a gmsh options file; "" for the mesh's own MESH.msh.opt.
  std::optional<std::string> gmshView;
  bool quiet = false;
  bool timings = false;         // --timings: the preparation's stages on stderr
  bool buildAlongside = false;  // --build-alongside (RenderRequest::buildAlongside)
  // Results (docs/results.md): --step K, --warp FIELD[:FACTOR], --color-by FIELD[:COMPONENT],
  // --color-map NAME, --undeformed edges|ghost, applied to every mesh.
  std::optional<int> step;
  std::string warp;
  std::string colorBy;
  std::string colorMap;
  std::string undeformed;
  std::string integrator;               // --integrator whitted|path|ao
  std::optional<double> noise;          // --noise: adaptive stop, in (0, 1)
  std::optional<double> adaptiveNoise;  // --adaptive-noise: adaptive rounds, in (0, 1)
  std::string look;                     // --look studio|sky|sun
  // Annotations on every mesh (docs/annotations.md), as the scene keys name them:
  std::string range;               // --range MIN:MAX, the colour range
  bool log = false;                // --log: the colours on a log scale
  std::string legend;              // --legend right|bottom|none, in the picture
  std::optional<int> isolines;     // --isolines N: lines of the --color-by field
  std::optional<int> bands;        // --bands N
  std::string arrows;              // --arrows FIELD
  std::string arrowGrid;           // --arrow-grid NX,NY,NZ: the arrows through the volume
  std::vector<std::string> clips;  // --clip AXIS=VALUE or PX,PY,PZ,NX,NY,NZ, any number
  // Inside the volume (docs/volume.md): --slice PLANE (any number), --skin STYLE,
  // --isosurfaces FIELD[:COUNT], --isovalues V1,V2,...
  std::vector<std::string> slices;
  std::string skin;
  std::string isosurfaces;
  std::string isovalues;
  std::string streamlines;       // --streamlines FIELD[:COUNT]
  std::string seedLine;          // --seed-line X1,Y1,Z1,X2,Y2,Z2
  std::string seedRectangle;     // --seed-rectangle X,Y,Z,UX,UY,UZ,VX,VY,VZ
  std::string streamlineRadius;  // --streamline-radius R or Npx
  // The inputs after the mesh: list-based .pos views put on it by their elements' coordinates.
  std::vector<std::string> views;
};

// The option groups of `lancer render --help` and `lancer animate --help`.
inline constexpr const char* kInputGroup = "Input";
inline constexpr const char* kCameraGroup = "Camera";
inline constexpr const char* kLookGroup = "Look";
inline constexpr const char* kResultsGroup = "Results";
inline constexpr const char* kVolumeGroup = "Inside the volume";
inline constexpr const char* kOutputGroup = "Output";
inline constexpr const char* kQualityGroup = "Quality";
inline constexpr const char* kClusterGroup = "Cluster";

// The options `render` and `animate` share, in the --help groups they belong to: what is seen
// (Camera, Look, Results), then how the picture is made (Output, Quality). A command adds its own
// -o between the two, so that it leads the Output group.
void addSceneViewOptions(CLI::App& command, SceneOverrides& overrides);
void addSceneOutputOptions(CLI::App& command, SceneOverrides& overrides);

// The command's inputs, positional: `lancer render|animate INPUT [VIEW.pos ...]`. Not required by
// CLI11, since --gmsh-view's value is optional and CLI11 gives it the input when it comes first
// (`lancer render --gmsh-view part.msh -o x.png`); takeInputFromGmshView puts it back.
CLI::Option* addInputOption(CLI::App& command, std::vector<std::string>& inputs);
// Called by the command's callback, once the line is parsed: with no input, the value of
// --gmsh-view is the input unless it is an options file (FILE.opt), and --gmsh-view then reads the
// default MESH.msh.opt. Throws CLI::RequiredError when there is still no input.
void takeInputFromGmshView(std::vector<std::string>& inputs, SceneOverrides& overrides);
// The input that gives the picture its geometry (a scene, a mesh, a pattern of step files): the
// first that is not a view file, or the first when all are (`lancer render az.pos b.pos`). The
// others go to `views`; one of them that is no view file (a second mesh) is an InputError.
std::string takeMeshInput(const std::vector<std::string>& inputs, std::vector<std::string>& views);

// "timings: read 0.052 s, orient 0.081 s, ..." (--timings).
std::string formatStageTimes(const StageTimes& stages);

// Asked once the overrides are applied, before any mesh of a scene file is loaded, for the memory check.
using ImageBufferChoice = std::function<ImageBuffer(const RenderSettings&)>;

// The command's input and options as a RenderRequest: a scene file (.toml), or the quick look of a
// mesh (.msh or .pos, read here, with overrides.views put on it), with --up and --gmsh-view applied; then
// prepareRender (render/render_preparation.hpp) checks the image's memory against the budget (--max-memory),
// builds the scene, the accelerator and the camera. The meshes' warnings go to stderr unless --quiet. Without
// a choice the image is held whole. keepMeshes: the meshes as read (every step of their views) stay in
// PreparedRender::meshes, for an animation over steps.
PreparedRender prepareScene(const std::string& input, const SceneOverrides& overrides,
                            const ImageBufferChoice& imageBuffer = {}, bool keepMeshes = false);

// Whether `input` is a scene file whose [animation] says over = "steps" (read once more, before the
// meshes, so that they are kept for the frames).
bool sceneAnimatesOverSteps(const std::string& input);

// --transparent asks for alpha: an output without it (.bmp, .ppm) is refused (InputError at the option).
void checkTransparentOutput(const SceneOverrides& overrides, const std::string& output);

// Ctrl-C and SIGTERM set the flag instead of killing the process, so outputs stay untouched.
const std::atomic<bool>& installInterruptHandler();

// True when progress lines should go to stderr (a terminal, and not --quiet).
bool showProgress(const SceneOverrides& overrides);

// How the settings want images written: the sRGB curve or linear, alpha with a transparent background,
// JPEG/WebP quality, and the metadata (DPI, lancer's version and the command line of setCommandLine).
ImageWriteOptions imageWriteOptions(const RenderSettings& settings);
// The command line the pictures record as how they were made (main calls it once).
void setCommandLine(int argc, const char* const* argv);
// lancer's version and that command line, for pictures written without render settings (assemble).
ImageMetadata commandProvenance();

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
