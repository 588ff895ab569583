#include "scene_setup.hpp"

#include "commands.hpp"
#include "volume_options.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/color_map.hpp"
#include "lancer/image/image.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/clip_text.hpp"
#include "lancer/scene/looks.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/gmsh_post_options.hpp"
#include "lancer/scene/results/gmsh_view.hpp"
#include "lancer/scene/results/step_files.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/scene/setting_checks.hpp"
#include "lancer/scene/suggest.hpp"
#include "lancer/scene/view_presets.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer::cli {
namespace {

std::atomic<bool> gInterrupted{false};
// The temporary files go at once, not only when the command unwinds: under mpirun a SIGTERM can be
// followed by SIGKILL before the render has stopped.
extern "C" void onInterrupt(int) {
  removePendingTemporaryFiles();
  gInterrupted.store(true);
}

// ".msh" for part.MSH: a file name's extension in lower case.
std::string lowerCaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// An option as setting_checks.hpp's functions name it.
SettingName optionName(const char* option) { return {SourceLocation{option}, option}; }

// --width, --height, --samples, --max-depth, --threads (the checks the scene file's keys and Python's
// arguments go through too) and --azimuth, --elevation, --zoom, before any file is read.
void checkOptionValues(const SceneOverrides& overrides) {
  if (overrides.width) checkWidth(*overrides.width, optionName("--width"));
  if (overrides.height) checkHeight(*overrides.height, optionName("--height"));
  if (overrides.samples) checkSamples(*overrides.samples, optionName("--samples"));
  if (overrides.maxDepth) checkMaxDepth(*overrides.maxDepth, optionName("--max-depth"));
  checkThreads(overrides.threads, optionName("--threads"));
  if (overrides.azimuth) checkAzimuth(*overrides.azimuth, optionName("--azimuth"));
  if (overrides.elevation) checkElevation(*overrides.elevation, optionName("--elevation"));
  if (overrides.zoom) checkZoom(*overrides.zoom, optionName("--zoom"));
}

// --tonemap, --exposure, --bit-depth, --denoise, checked here so that the messages name the option.
void applyOutputOverrides(const SceneOverrides& overrides, RenderOverrides& applied) {
  if (!overrides.toneMap.empty()) {
    applied.toneMap = enumFromName<ToneMap>(kToneMapNames, overrides.toneMap);
    if (!applied.toneMap)
      throw InputError(SourceLocation{"--tonemap"},
                       fmt::format("unknown tone map '{}': use none, filmic or aces", overrides.toneMap));
  }
  if (overrides.exposure) applied.exposure = checkExposure(*overrides.exposure, optionName("--exposure"));
  if (overrides.bitDepth) applied.bitDepth = checkBitDepth(*overrides.bitDepth, optionName("--bit-depth"));
  if (overrides.quality) applied.quality = *overrides.quality;  // checked by applyRenderOverrides
  if (overrides.lossless) applied.lossless = true;
  if (overrides.dpi) applied.dpi = *overrides.dpi;
  if (overrides.denoise) applied.denoise = true;
}

// --color-map on every coloured mesh; `required`: an error when none is coloured.
void applyColorMap(SceneDescription& description, const std::string& text, bool required) {
  if (text.empty()) return;
  const SourceLocation where{"--color-map"};
  const ColorMap map = colorMapFromText(text, where);
  bool coloured = false;
  for (MeshInstance& mesh : description.meshes)
    if (mesh.colorBy) {
      mesh.colorBy->map = map;
      coloured = true;
    }
  if (!coloured && required)
    throw InputError(where,
                     "no mesh is coloured by a field: give --color-by FIELD too (or color_by in the scene)");
}

// --step, --warp, --color-by, --color-map and --undeformed on every mesh of the description.
void applyResultOverrides(SceneDescription& description, const SceneOverrides& overrides) {
  if (overrides.step) description.when = StepSelection{overrides.step, std::nullopt, "--step"};
  if (!overrides.warp.empty()) {
    const std::size_t colon = overrides.warp.rfind(':');
    WarpSettings warp;
    warp.field = overrides.warp.substr(0, colon);
    warp.where = SourceLocation{"--warp"};
    if (colon != std::string::npos) {
      const std::string factor = overrides.warp.substr(colon + 1);
      char* end = nullptr;
      warp.factor = std::strtod(factor.c_str(), &end);
      if (factor.empty() || end != factor.c_str() + factor.size() || !std::isfinite(warp.factor))
        throw InputError(SourceLocation{"--warp"},
                         fmt::format("'{}' is not FIELD[:FACTOR]: the factor '{}' is not a number (e.g. "
                                     "--warp displacement:2)",
                                     overrides.warp, factor));
    }
    if (warp.field.empty())
      throw InputError(
          SourceLocation{"--warp"},
          fmt::format("'{}' names no field: use FIELD[:FACTOR], e.g. --warp displacement:2", overrides.warp));
    for (MeshInstance& mesh : description.meshes) mesh.warp = warp;
  }
  if (!overrides.colorBy.empty()) {
    const std::size_t colon = overrides.colorBy.rfind(':');
    ColorBy color;
    color.field = overrides.colorBy.substr(0, colon);
    color.where = SourceLocation{"--color-by"};
    if (colon != std::string::npos) {
      const std::string text = overrides.colorBy.substr(colon + 1);
      const std::optional<FieldComponent> component = parseFieldComponent(text);
      if (!component)
        throw InputError(SourceLocation{"--color-by"},
                         fmt::format("'{}' is not a component: use magnitude, x, y, z, 0 to 8 or von_mises "
                                     "(--color-by FIELD[:COMPONENT])",
                                     text));
      color.component = *component;
    }
    for (MeshInstance& mesh : description.meshes) {
      if (mesh.colorBy) color.map = mesh.colorBy->map;
      mesh.colorBy = color;
    }
  }
  // With --gmsh-view the view may colour the mesh: the map is applied again once it has.
  // Isosurfaces, field lines and arrows take the map when no mesh is coloured (render_overrides.hpp).
  applyColorMap(description, overrides.colorMap,
                !overrides.gmshView && overrides.isosurfaces.empty() && overrides.streamlines.empty() &&
                    overrides.arrows.empty());
  if (!overrides.undeformed.empty()) {
    const UndeformedStyle style = overrides.undeformed == "edges"   ? UndeformedStyle::Edges
                                  : overrides.undeformed == "ghost" ? UndeformedStyle::Ghost
                                                                    : UndeformedStyle::None;
    for (MeshInstance& mesh : description.meshes)
      if (mesh.warp) mesh.undeformed = style;
  }
}

// A whole string as a number, or nothing.
std::optional<double> numberOf(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

// --log, --range, --legend, --isolines, --bands, --arrows and --clip turned into values; the renderer's
// overrides check them (render_overrides.hpp).
void applyAnnotationOptions(const SceneOverrides& overrides, RenderOverrides& applied) {
  if (!overrides.range.empty()) {
    // MIN:MAX; the colon that splits them is the one a number cannot hold.
    const std::size_t colon = overrides.range.find(':');
    const std::optional<double> low =
        colon == std::string::npos ? std::nullopt : numberOf(overrides.range.substr(0, colon));
    const std::optional<double> high =
        colon == std::string::npos ? std::nullopt : numberOf(overrides.range.substr(colon + 1));
    if (!low || !high)
      throw InputError(SourceLocation{"--range"},
                       fmt::format("'{}' is not MIN:MAX: give the values at the map's two ends, e.g. --range "
                                   "0:250 or --range -1e-3:1e-3",
                                   overrides.range));
    applied.range = std::pair{*low, *high};
  }
  if (!overrides.legend.empty()) {
    applied.legend = enumFromName<LegendPlacement>(kLegendPlacementNames, overrides.legend);
    if (!applied.legend)
      throw InputError(SourceLocation{"--legend"},
                       fmt::format("'{}' is not a place for the legend: use right, bottom or none (render "
                                   "--legend-file FILE.png writes it to its own image)",
                                   overrides.legend));
  }
  if (overrides.log) applied.scale = ColorScale::Log;
  applied.isolines = overrides.isolines;
  applied.bands = overrides.bands;
  if (!overrides.arrows.empty()) {
    ArrowSpec arrows = arrowsOfField(overrides.arrows, SourceLocation{"--arrows"});
    if (!overrides.arrowGrid.empty()) arrows.grid = arrowGridFromText(overrides.arrowGrid, "--arrow-grid");
    applied.annotations.push_back(arrows);
  } else if (!overrides.arrowGrid.empty()) {
    throw InputError(SourceLocation{"--arrow-grid"},
                     "--arrow-grid places the arrows of a vector field through the volume: give the field "
                     "with --arrows FIELD");
  }
  for (const std::string& clip : overrides.clips)
    applied.clips.push_back(clipFromText(clip, SourceLocation{"--clip"}));
  applyVolumeOptions(overrides, applied);
  // Isosurfaces, field lines and arrows take the map when no mesh is coloured (render_overrides.cpp).
  if (!overrides.colorMap.empty() &&
      (!overrides.isosurfaces.empty() || !overrides.streamlines.empty() || !overrides.arrows.empty()))
    applied.colorMap = colorMapFromText(overrides.colorMap, SourceLocation{"--color-map"});
}

// --background: a CSS name, #rrggbb or #rgb (parseColor), or r,g,b with each in [0, 1]; the colour the
// picture shows.
Vec3 backgroundFromText(const std::string& text) {
  if (const std::optional<Vec3> color = parseColor(text)) return *color;
  std::array<double, 3> rgb{};
  std::size_t start = 0;
  int count = 0;
  bool numbers = true;
  while (numbers && start <= text.size() && count < 4) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::optional<double> value = numberOf(text.substr(start, comma - start));
    numbers = value && *value >= 0 && *value <= 1;
    if (numbers && count < 3) rgb[count] = *value;
    ++count;
    start = comma + 1;
  }
  if (numbers && count == 3) return toFloat(Vec3d{rgb[0], rgb[1], rgb[2]});
  const std::vector<std::string_view> names = colorNames();
  throw InputError(
      SourceLocation{"--background"},
      fmt::format("'{}' is not a colour{}: use a CSS colour name (white, navy), #rrggbb, #rgb or "
                  "r,g,b with each in 0..1 (e.g. 1,1,1)",
                  text, didYouMean(text, std::span<const std::string_view>(names))));
}

// --view, --azimuth, --elevation and --zoom on the description's camera (docs/rendering.md): the
// automatic camera turns its view direction; a scene's placed camera turns about its look_at.
// Returns whether any was given.
bool applyCameraOptions(SceneDescription& description, const SceneOverrides& overrides) {
  const bool turns = overrides.azimuth || overrides.elevation;
  if (overrides.view.empty() && !turns && !overrides.zoom) return false;
  const char* first = !overrides.view.empty() ? "--view"
                      : overrides.azimuth     ? "--azimuth"
                      : overrides.elevation   ? "--elevation"
                                              : "--zoom";
  CameraSettings& camera = description.camera;
  if (overrides.gmshView || camera.gmshView)
    throw InputError(SourceLocation{first},
                     fmt::format("{} places the camera as gmsh shows it: turn and zoom the view in gmsh, or "
                                 "leave {} out",
                                 overrides.gmshView ? "--gmsh-view" : "the scene's camera.gmsh_view", first));
  OrbitAngles angles;
  if (overrides.azimuth) angles.azimuthDegrees = checkAzimuth(*overrides.azimuth, optionName("--azimuth"));
  if (overrides.elevation)
    angles.elevationDegrees = checkElevation(*overrides.elevation, optionName("--elevation"));
  const double zoom = overrides.zoom ? checkZoom(*overrides.zoom, optionName("--zoom")) : 1.0;
  Vec3d axis = camera.up;  // the model's up, which --azimuth turns about
  if (!overrides.view.empty()) {
    const std::optional<ViewPreset> preset = parseViewPreset(overrides.view);
    if (camera.position)
      throw InputError(
          SourceLocation{"--view"},
          fmt::format("{} places its camera (camera.position): --view chooses the side of the "
                      "automatic camera; turn this one with --azimuth and --elevation, or remove "
                      "camera.position",
                      description.path));
    const std::optional<UpAxis> up = upAxisOf(camera.up);
    if (!preset || !up)
      throw InputError(
          SourceLocation{"--view"},
          fmt::format("the camera's up [{}, {}, {}] is along no axis: --view names its sides from "
                      "an up axis (set camera.up_axis, or --up x|y|z|-x|-y|-z)",
                      camera.up.x, camera.up.y, camera.up.z));
    const ViewFrame frame = presetFrame(*preset, *up);
    camera.up = frame.up;
    camera.viewFrom = frame.toViewer;
    camera.viewChosen = true;
    axis = upVector(*up);
  }
  if (turns) {
    if (camera.position) {
      if (!camera.lookAt)
        throw InputError(SourceLocation{first},
                         fmt::format("{} places its camera without camera.look_at: --azimuth and --elevation "
                                     "turn it about its look_at; add look_at to [camera]",
                                     description.path));
      Vec3d toViewer = *camera.position - *camera.lookAt;
      turnView(toViewer, camera.up, axis, angles);
      camera.position = *camera.lookAt + toViewer;
    } else {
      turnView(camera.viewFrom, camera.up, axis, angles);
      camera.viewChosen = true;
    }
  }
  if (!overrides.view.empty() || turns) {
    // `animate` turns the camera about the model's up, not about the turned camera's own up.
    if (!description.animation) description.animation.emplace();
    if (!description.animation->axis) description.animation->axis = axis;
  }
  camera.zoom = zoom;
  return true;
}

}  // namespace

CLI::Option* addInputOption(CLI::App& command, std::vector<std::string>& inputs) {
  return command
      .add_option("input", inputs,
                  "Scene file (.toml), or gmsh mesh (.msh) or list-based view (.pos), then .pos views "
                  "to put on that mesh; required")
      ->group(kInputGroup);
}

void takeInputFromGmshView(std::vector<std::string>& inputs, SceneOverrides& overrides) {
  // `--gmsh-view magnet.msh az.pos`: the mesh went to --gmsh-view, the views to the inputs.
  const auto tookTheMesh = [&] {
    if (!overrides.gmshView || overrides.gmshView->empty() ||
        lowerCaseExtension(*overrides.gmshView) == ".opt")
      return false;
    return inputs.empty() ||
           (std::all_of(inputs.begin(), inputs.end(), isViewFile) && !isViewFile(*overrides.gmshView));
  };
  if (tookTheMesh()) {
    inputs.insert(inputs.begin(), *overrides.gmshView);
    overrides.gmshView = "";
  }
  if (inputs.empty()) throw CLI::RequiredError("input");
}

std::string takeMeshInput(const std::vector<std::string>& inputs, std::vector<std::string>& views) {
  std::vector<bool> view(inputs.size());
  std::size_t mesh = inputs.size();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    view[i] = inputs.size() > 1 && isViewFile(inputs[i]);
    if (!view[i] && mesh == inputs.size()) mesh = i;
  }
  if (mesh == inputs.size()) mesh = 0;
  views.clear();
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (i == mesh) continue;
    std::error_code error;
    if (!view[i] && !std::filesystem::exists(inputs[i], error))
      throw InputError(SourceLocation{inputs[i]}, "cannot open the view file: No such file or directory");
    if (!view[i])
      throw InputError(
          SourceLocation{inputs[i]},
          fmt::format("one mesh or scene per command: {} gives the geometry, and the inputs after it "
                      "are list-based .pos views to put on it, which this is not",
                      inputs[mesh]));
    views.push_back(inputs[i]);
  }
  return inputs[mesh];
}

PreparedRender prepareScene(const std::string& input, const SceneOverrides& overrides,
                            const ImageBufferChoice& imageBuffer, bool keepMeshes) {
  checkOptionValues(overrides);
  std::optional<Vec3> background;
  if (!overrides.background.empty()) background = backgroundFromText(overrides.background);
  std::optional<UpAxis> up;
  if (!overrides.up.empty()) {
    up = parseUpAxis(overrides.up);
    if (!up)
      throw InputError(SourceLocation{"--up"},
                       fmt::format("'{}' is not an axis: use x, y, z, -x, -y or -z", overrides.up));
  }
  RenderRequest request;
  SceneDescription& description = request.description;
  if (isStepFilePattern(input)) {  // a quoted "result_*.msh": one step per file
    const Stopwatch read;
    request.quickLookMesh = readStepFiles(input, matchStepFiles(input, SourceLocation{input}),
                                          overrides.threads, SourceLocation{input});
    addViewFiles(*request.quickLookMesh, overrides.views);
    request.stages.add("read", read.seconds());
    const Stopwatch setup;  // colours, up axis and lights: passes over every face
    description = quickLookScene(input, *request.quickLookMesh, up, overrides.threads);
    if (applyCameraOptions(description, overrides))  // the lights follow the camera
      placeQuickLookLights(description, *request.quickLookMesh, overrides.threads);
    request.stages.add("setup", setup.seconds());
  } else if (isMeshFile(input)) {
    const Stopwatch read;
    if (!overrides.slices.empty() || !overrides.isosurfaces.empty() || !overrides.streamlines.empty() ||
        !overrides.arrowGrid.empty() || (!overrides.clips.empty() && !overrides.colorBy.empty())) {
      MeshWithVolume withVolume = readMeshFileWithVolume(input, overrides.threads);
      addViewFiles(withVolume, overrides.views);
      request.quickLookMesh = std::move(withVolume.mesh);
      request.quickLookVolume = std::move(withVolume.volume);
    } else {
      request.quickLookMesh = readMeshFile(input, overrides.threads);
      addViewFiles(*request.quickLookMesh, overrides.views);
    }
    request.stages.add("read", read.seconds());
    if (const std::string reason = nothingToDrawReason(*request.quickLookMesh); !reason.empty())
      throw InputError(SourceLocation{input}, "nothing to draw: " + reason);
    const Stopwatch setup;  // colours, up axis and lights: passes over every face
    description = quickLookScene(input, *request.quickLookMesh, up, overrides.threads);
    if (applyCameraOptions(description, overrides))  // the lights follow the camera
      placeQuickLookLights(description, *request.quickLookMesh, overrides.threads);
    request.stages.add("setup", setup.seconds());
  } else {
    if (!overrides.views.empty())
      throw InputError(SourceLocation{overrides.views.front()},
                       fmt::format("views on the command line go on a mesh given there (lancer render "
                                   "part.msh {}); {} is a scene file: give them to its mesh with views = "
                                   "[\"{}\"] in its [[mesh]]",
                                   overrides.views.front(), input, overrides.views.front()));
    description = loadScene(input);
    if (up) applyUpAxis(description.camera, *up);
    applyCameraOptions(description, overrides);
  }
  if (overrides.gmshView) {
    // gmsh reads part.msh.opt beside part.msh whenever it opens it: the same file by default.
    std::string path = *overrides.gmshView;
    if (path.empty() && !description.meshes.empty()) path = description.meshes.front().file + ".opt";
    description.camera.gmshView = readGmshView(path);
    // Its View[i] options (steps, warps, ranges) need the views' names: applied to the meshes read.
    request.withMeshes = [views = readGmshPostViews(path), path, colorMap = overrides.colorMap](
                             SceneDescription& scene, const std::vector<Mesh>& meshes) {
      if (!meshes.empty()) applyGmshPostViews(scene, meshes.front(), views, path);
      applyColorMap(scene, colorMap, true);
    };
    if (request.quickLookMesh)  // from gmsh's side
      placeQuickLookLights(description, *request.quickLookMesh, overrides.threads);
  }
  RenderOverrides& applied = request.overrides;
  applied.width = overrides.width;
  applied.height = overrides.height;
  applied.samples = overrides.samples;
  applied.maxDepth = overrides.maxDepth;
  if (overrides.srgb) applied.srgb = true;
  if (overrides.linear) applied.srgb = false;
  applyOutputOverrides(overrides, applied);
  applied.backgroundDisplay = background;
  if (overrides.transparent) applied.transparentBackground = true;
  if (!overrides.sampler.empty())
    applied.sampler = enumFromName<SamplerKind>(kSamplerNames, overrides.sampler);
  if (!overrides.shading.empty())
    applied.shading = enumFromName<ShadingMode>(kShadingNames, overrides.shading);
  applied.edges = overrides.edges;
  if (!overrides.integrator.empty())
    applied.integrator = enumFromName<IntegratorKind>(kIntegratorNames, overrides.integrator);
  if (overrides.noise) applied.noise = checkNoise(*overrides.noise, optionName("--noise"));
  if (overrides.adaptiveNoise)
    applied.adaptiveNoise = checkAdaptiveNoise(*overrides.adaptiveNoise, optionName("--adaptive-noise"));
  if (!overrides.look.empty()) applied.look = enumFromName<Look>(kLookNames, overrides.look);
  applyAnnotationOptions(overrides, applied);
  request.accel = parseAccelKind(overrides.accel);
  request.threads = overrides.threads;
  request.imageBuffer = imageBuffer;
  request.keepMeshes = keepMeshes;
  request.buildAlongside = overrides.buildAlongside;
  applyResultOverrides(description, overrides);
  PreparedRender prepared = prepareRender(std::move(request));
  if (!overrides.quiet)
    for (const std::string& warning : prepared.scene.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
  return prepared;
}

void checkTransparentOutput(const SceneOverrides& overrides, const std::string& output) {
  if (!overrides.transparent) return;
  const std::string extension = lowerCaseExtension(output);
  if (extension != ".png" && extension != ".exr" && extension != ".gif" && extension != ".webp")
    throw InputError(
        SourceLocation{"--transparent"},
        fmt::format("{} has no alpha channel for a transparent background: write a .png, .webp, .exr or "
                    ".gif",
                    output));
}

bool sceneAnimatesOverSteps(const std::string& input) {
  if (isStepFilePattern(input) || isMeshFile(input)) return false;
  const SceneDescription description = loadScene(input);
  return description.animation && description.animation->overSteps;
}

std::string formatStageTimes(const StageTimes& stages) {
  std::string line = "timings:";
  const char* separator = " ";
  for (const StageTimes::Stage& stage : stages.stages) {
    line += fmt::format("{}{} {:.3f} s", separator, stage.name, stage.seconds);
    separator = ", ";
  }
  return line;
}

const std::atomic<bool>& installInterruptHandler() {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  return gInterrupted;
}

bool showProgress(const SceneOverrides& overrides) { return !overrides.quiet && isatty(STDERR_FILENO); }

namespace {
std::string gCommandLine;  // set once by main, before any thread starts
}  // namespace

// The program as "lancer", not the path it was started by (which says where it was built or installed).
void setCommandLine(int argc, const char* const* argv) {
  std::vector<const char*> words(argv, argv + argc);
  if (!words.empty()) words[0] = "lancer";
  gCommandLine = quoteCommandLine(argc, words.data());
}

ImageMetadata commandProvenance() {
  ImageMetadata metadata;
  metadata.software = softwareName();
  metadata.command = gCommandLine;
  return metadata;
}

ImageWriteOptions imageWriteOptions(const RenderSettings& settings) {
  ImageWriteOptions options;
  options.curve = settings.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  options.bitDepth = settings.bitDepth;
  options.alpha = settings.transparentBackground ? AlphaChannel::Always : AlphaChannel::Never;
  options.quality = settings.quality;
  options.lossless = settings.lossless;
  options.metadata = commandProvenance();
  options.metadata.dpi = settings.dpi;
  return options;
}

RenderOptions commandRenderOptions(const SceneOverrides& overrides) {
  RenderOptions options;
  options.threads = overrides.threads;
  options.cancel = &installInterruptHandler();
  // LANCER_SINGLE_RAYS=1: every ray traced on its own (the same image), to measure the packets.
  const char* singleRays = std::getenv("LANCER_SINGLE_RAYS");
  options.packets = !(singleRays != nullptr && std::string_view(singleRays) == "1");
  return options;
}

void addAnimationWriterOptions(CLI::App& command, AnimationOutputOptions& writer) {
  command
      .add_option("--loop", writer.loop,
                  fmt::format("Repeats after the first showing: 0 forever (default), -1 play once, up to {}",
                              kMaxLoop))
      ->group(kOutputGroup);
  command.add_option("--dither", writer.dither, "GIF dithering: ordered (default), floyd-steinberg or none")
      ->check(CLI::IsMember({"none", "ordered", "floyd-steinberg"}))
      ->group(kOutputGroup);
  command.add_option("--palette", writer.palette, "GIF palette: global (default, no flicker) or per-frame")
      ->check(CLI::IsMember({"global", "per-frame"}))
      ->group(kOutputGroup);
}

bool interruptRequested() { return gInterrupted.load(); }

int interruptedExit(const std::string& output) {
  std::fprintf(stderr, "lancer: interrupted; %s was not written\n", output.c_str());
  return kExitInterrupted;
}

}  // namespace lancer::cli
