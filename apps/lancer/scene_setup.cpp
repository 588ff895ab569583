#include "scene_setup.hpp"

#include "commands.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image.hpp"
#include "lancer/mesh/msh/foreign_formats.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/nothing_to_draw.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/gmsh_view.hpp"
#include "lancer/scene/looks.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/render_overrides.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/memory_budget.hpp"
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

// A .msh by name, or a file that is no scene: a mesh by content, or a file that is neither (a .geo,
// STL, STEP, ...), which the mesh reader names with the gmsh command that makes a mesh of it.
bool isMeshFile(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".msh") return true;
  if (extension == ".toml") return false;
  std::ifstream in(path, std::ios::binary);
  std::vector<char> head(4096);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return looksLikeMsh(head) || !foreignFileMessage(head, error ? 0 : size, path).empty();
}

// The command line checks its choices against the same tables (CLI11 wants strings).
template <std::size_t N>
std::vector<std::string> choices(const std::array<std::string_view, N>& names) {
  return {names.begin(), names.end()};
}

// Checked before loading any mesh. Whole: the float image and its 8-bit copy for the writer.
// Bands: the bands renderBands keeps, plus the writer's encoded row and libpng's and zlib's state
// (well under kWriterStateBytes), whatever the height.
void requireImageMemory(const RenderSettings& settings, int threads, ImageBuffer buffer,
                        const std::string& input) {
  constexpr std::uint64_t kWriterStateBytes = 1 << 20;
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(settings.width) * static_cast<std::uint64_t>(settings.height);
  if (buffer == ImageBuffer::Whole) {
    requireMemory(saturatingProduct(pixels, sizeof(Rgba) + 4), SourceLocation{input},
                  fmt::format("a {}x{} image", settings.width, settings.height));
    return;
  }
  const std::uint64_t bytes = bandMemoryBytes(settings.width, settings.height, threads) +
                              static_cast<std::uint64_t>(settings.width) * 4 + kWriterStateBytes;
  requireMemory(
      bytes, SourceLocation{input},
      fmt::format("a {}x{} image rendered in bands of {} rows", settings.width, settings.height, kTileSize));
}

}  // namespace

void addSceneOverrideOptions(CLI::App& command, SceneOverrides& overrides) {
  command.add_option("--width", overrides.width, "Image width in pixels")
      ->check(CLI::Range(1, kMaxRenderSide));
  command.add_option("--height", overrides.height, "Image height in pixels")
      ->check(CLI::Range(1, kMaxRenderSide));
  command
      .add_option("--samples", overrides.samples, "Samples per pixel (a perfect square for the regular grid)")
      ->check(CLI::Range(1, kMaxSamples));
  command.add_option("--sampler", overrides.sampler, "Anti-aliasing: regular, stratified or adaptive")
      ->check(CLI::IsMember(choices(kSamplerNames)));
  command.add_option("--max-depth", overrides.maxDepth, "Reflection/refraction depth")
      ->check(CLI::Range(0, kMaxDepth));
  command.add_option("--shading", overrides.shading, "Shading for every mesh: flat, gouraud or phong")
      ->check(CLI::IsMember(choices(kShadingNames)));
  command
      .add_option(
          "--accel", overrides.accel,
          "Accelerator: kdtree-sah (default), kdtree-sah-exact (slower build, the quality reference), "
          "kdtree-median or naive")
      ->check(CLI::IsMember(choices(kAccelNames)));
  command.add_option("--threads", overrides.threads, "Worker threads (default 0: all cores)")
      ->check(CLI::Range(0, kMaxThreads));
  command.add_flag("--srgb", overrides.srgb, "Encode the output with the sRGB curve instead of linear");
  command.add_flag("--edges", overrides.edges,
                   "Draw element edges (1 pixel, black) on every mesh whose scene sets no edges");
  command.add_option("--up", overrides.up,
                     "Up axis of the automatic camera: x, y, z, -x, -y or -z (a bare mesh: guessed; a scene: "
                     "y)");
  command
      .add_option("--gmsh-view", overrides.gmshView,
                  "The view set up in gmsh: its options file (File > Save Model Options; default: the mesh's "
                  "MESH.msh.opt)")
      ->expected(0, 1);
  command
      .add_option("--integrator", overrides.integrator,
                  "How light is carried: whitted (the default, the brief's model), path (path tracing) or ao "
                  "(ambient occlusion); see docs/lighting.md")
      ->check(CLI::IsMember(choices(kIntegratorNames)));
  command.add_option("--noise", overrides.noise,
                     "path, ao: stop sampling a pixel once its relative error is below this (0 < noise < 1)");
  command
      .add_option("--look", overrides.look,
                  "A lit scene in one option (path tracing, soft light, sky, a floor catching shadows): "
                  "studio, sky or sun")
      ->check(CLI::IsMember(choices(kLookNames)));
  command.add_flag("-q,--quiet", overrides.quiet, "No progress or summary on stderr");
  command.add_flag("--timings", overrides.timings,
                   "Print where the time before the first ray went: read, orient (shells, orientation, "
                   "nesting), normals, scene, kd build");
}

PreparedScene prepareScene(const std::string& input, const SceneOverrides& overrides,
                           const ImageBufferChoice& imageBuffer) {
  const Stopwatch load;
  std::optional<UpAxis> up;
  if (!overrides.up.empty()) {
    up = parseUpAxis(overrides.up);
    if (!up)
      throw InputError(SourceLocation{"--up"},
                       fmt::format("'{}' is not an axis: use x, y, z, -x, -y or -z", overrides.up));
  }
  SceneDescription description;
  StageTimes stages;
  std::vector<Mesh> preloaded;
  if (isMeshFile(input)) {
    const Stopwatch read;
    preloaded.push_back(readMsh(input, overrides.threads));
    stages.add("read", read.seconds());
    if (const std::string reason = nothingToDrawReason(preloaded.front()); !reason.empty())
      throw InputError(SourceLocation{input}, "nothing to draw: " + reason);
    description = quickLookScene(input, preloaded.front(), up);
  } else {
    description = loadScene(input);
    if (up) applyUpAxis(description.camera, *up);
  }
  if (overrides.gmshView) {
    // gmsh reads part.msh.opt beside part.msh whenever it opens it: the same file by default.
    std::string path = *overrides.gmshView;
    if (path.empty() && !description.meshes.empty()) path = description.meshes.front().file + ".opt";
    description.camera.gmshView = readGmshView(path);
    if (!preloaded.empty()) placeQuickLookLights(description, preloaded.front());  // lit from gmsh's side
  }
  RenderOverrides applied;
  applied.width = overrides.width;
  applied.height = overrides.height;
  applied.samples = overrides.samples;
  applied.maxDepth = overrides.maxDepth;
  if (overrides.srgb) applied.srgb = true;
  if (!overrides.sampler.empty())
    applied.sampler = enumFromName<SamplerKind>(kSamplerNames, overrides.sampler);
  if (!overrides.shading.empty())
    applied.shading = enumFromName<ShadingMode>(kShadingNames, overrides.shading);
  applied.edges = overrides.edges;
  if (!overrides.integrator.empty())
    applied.integrator = enumFromName<IntegratorKind>(kIntegratorNames, overrides.integrator);
  if (overrides.noise) {
    if (!(*overrides.noise > 0 && *overrides.noise < 1))
      throw InputError(SourceLocation{"--noise"},
                       fmt::format("--noise must be greater than 0 and less than 1 (a relative error, e.g. "
                                   "0.01), found {}",
                                   *overrides.noise));
    applied.noise = static_cast<float>(*overrides.noise);
  }
  if (!overrides.look.empty()) applied.look = enumFromName<Look>(kLookNames, overrides.look);
  applyRenderOverrides(description, applied, preloaded.empty() ? nullptr : &preloaded.front());
  requireImageMemory(description.render, overrides.threads,
                     imageBuffer ? imageBuffer(description.render) : ImageBuffer::Whole, input);
  Scene scene = preloaded.empty() ? buildScene(description, overrides.threads, &stages)
                                  : buildScene(description, std::move(preloaded), overrides.threads, &stages);
  if (!overrides.quiet)
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
  const double loadSeconds = load.seconds();
  const Stopwatch build;
  KdBuildOptions buildOptions;
  buildOptions.threads = overrides.threads;  // --threads bounds the build too, not only the trace
  Accelerator accelerator = Accelerator::build(scene.geometry.positions, scene.geometry.faces,
                                               parseAccelKind(overrides.accel), buildOptions);
  const double buildSeconds = build.seconds();
  stages.add("kd build", buildSeconds);
  return PreparedScene{std::move(description), std::move(scene), std::move(accelerator), loadSeconds,
                       buildSeconds,           std::move(stages)};
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

ImageWriteOptions imageWriteOptions(const RenderSettings& settings) {
  ImageWriteOptions options;
  options.curve = settings.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  options.alpha = settings.transparentBackground ? AlphaChannel::Always : AlphaChannel::Never;
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
      .add_option("--loop", writer.loop, "Repeats after the first showing: 0 forever (default), -1 play once")
      ->check(CLI::Range(-1, 65535));
  command.add_option("--dither", writer.dither, "GIF dithering: ordered (default), floyd-steinberg or none")
      ->check(CLI::IsMember({"none", "ordered", "floyd-steinberg"}));
  command.add_option("--palette", writer.palette, "GIF palette: global (default, no flicker) or per-frame")
      ->check(CLI::IsMember({"global", "per-frame"}));
}

bool interruptRequested() { return gInterrupted.load(); }

int interruptedExit(const std::string& output) {
  std::fprintf(stderr, "lancer: interrupted; %s was not written\n", output.c_str());
  return kExitInterrupted;
}

}  // namespace lancer::cli
