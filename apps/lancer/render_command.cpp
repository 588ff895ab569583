// `lancer render SCENE.toml | MESH.msh`: load, build the accelerator, trace, write the image.
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "lancer/accel/accelerator.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::cli {
namespace {

std::atomic<bool> gInterrupted{false};
extern "C" void onInterrupt(int) { gInterrupted.store(true); }

struct RenderCommandOptions {
  std::string input;
  std::string output;
  std::optional<int> width, height, samples, maxDepth;
  std::string shading;
  std::string accel = "kdtree-sah";
  std::string pixel;
  int threads = 0;
  bool srgb = false;
  bool quiet = false;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ShadingMode parseShading(const std::string& name) {
  if (name == "flat") return ShadingMode::Flat;
  if (name == "gouraud") return ShadingMode::Gouraud;
  if (name == "phong") return ShadingMode::Phong;
  throw InputError(SourceLocation{"--shading"}, fmt::format("unknown shading '{}': use flat, gouraud or phong", name));
}

bool isMeshFile(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".msh";
}

void printProgress(const RenderProgress& progress) {
  const double raysPerSecond = progress.seconds > 0 ? progress.rays / progress.seconds : 0;
  const double eta = progress.fraction > 0 ? progress.seconds * (1 - progress.fraction) / progress.fraction : 0;
  std::fprintf(stderr, "\r  %5.1f%%  %7.2f Mrays/s  ETA %5.1f s ", 100 * progress.fraction, raysPerSecond * 1e-6,
               eta);
  std::fflush(stderr);
}

int runRender(const RenderCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SceneDescription description;
  std::optional<Mesh> quickLookMesh;
  if (isMeshFile(options.input)) {
    quickLookMesh = readMsh(options.input);
    description = quickLookScene(options.input, *quickLookMesh);
  } else {
    description = loadScene(options.input);
  }
  RenderSettings& settings = description.render;
  if (options.width) settings.width = *options.width;
  if (options.height) settings.height = *options.height;
  if (options.samples) settings.samples = *options.samples;
  if (options.maxDepth) settings.maxDepth = *options.maxDepth;
  if (options.srgb) settings.srgb = true;
  if (!options.shading.empty()) {
    settings.shading = parseShading(options.shading);
    for (MeshInstance& mesh : description.meshes) mesh.shading.reset();
  }
  const std::string output = options.output.empty() ? settings.output : options.output;
  if (output.empty())
    throw InputError(SourceLocation{options.input}, "no output image: give -o FILE or set render.output");
  imageFormatFromPath(output);  // refuse a bad extension before spending time on the render

  Scene scene;
  if (quickLookMesh) {
    std::vector<Mesh> meshes;
    meshes.push_back(std::move(*quickLookMesh));
    scene = buildScene(description, std::move(meshes));
  } else {
    scene = buildScene(description);
  }
  const double loadSeconds = secondsSince(start);

  const auto buildStart = std::chrono::steady_clock::now();
  const Accelerator accelerator =
      Accelerator::build(scene.positions, scene.faces, parseAccelKind(options.accel));
  const double buildSeconds = secondsSince(buildStart);

  const Camera camera(description.camera, scene.origin, scene.bounds, settings.width, settings.height);
  if (!options.pixel.empty()) {
    int x = -1, y = -1;
    if (std::sscanf(options.pixel.c_str(), "%d,%d", &x, &y) != 2 || x < 0 || y < 0 || x >= settings.width ||
        y >= settings.height)
      throw InputError(SourceLocation{"--pixel"},
                       fmt::format("'{}' is not a pixel 'x,y' inside {}x{}", options.pixel, settings.width, settings.height));
    const Tracer tracer(scene, accelerator, settings);
    TraceCounters counters;
    std::uint64_t samples = 0;
    const Rgba value = renderPixel(tracer, camera, settings, x, y, counters, samples);
    std::printf("pixel %d,%d: rgb %.6f %.6f %.6f alpha %.3f (%llu samples, %llu rays)\n", x, y, value.r, value.g,
                value.b, value.a, static_cast<unsigned long long>(samples),
                static_cast<unsigned long long>(counters.rays));
    return kExitOk;
  }

  RenderOptions renderOptions;
  renderOptions.threads = options.threads;
  renderOptions.cancel = &gInterrupted;
  const bool showProgress = !options.quiet && isatty(STDERR_FILENO);
  if (showProgress) renderOptions.onProgress = printProgress;
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  RenderStats stats;
  const Image image = renderImage(scene, accelerator, camera, settings, renderOptions, &stats);
  if (showProgress) std::fputc('\n', stderr);
  if (gInterrupted.load()) {
    std::fprintf(stderr, "lancer: interrupted; %s was not written\n", output.c_str());
    return 130;
  }

  ImageWriteOptions writeOptions;
  writeOptions.curve = settings.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  writeOptions.alpha = settings.transparentBackground ? AlphaChannel::Always : AlphaChannel::Never;
  writeImage(output, image, writeOptions);
  if (!options.quiet) {
    std::fprintf(stderr,
                 "%s: %dx%d, %zu faces, load %.3f s, build %.3f s, trace %.3f s (%.2f Mrays/s), total %.3f s\n",
                 output.c_str(), settings.width, settings.height, scene.faces.size(), loadSeconds, buildSeconds,
                 stats.seconds, stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, secondsSince(start));
  }
  return kExitOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "render", "Render a scene file (.toml), or a mesh (.msh) with an automatic camera, lights and colours");
  command->add_option("input", options->input, "Scene file (.toml) or gmsh mesh (.msh)")->required();
  command->add_option("-o,--output", options->output,
                      fmt::format("Output image ({}); overrides render.output", kImageExtensions));
  command->add_option("--width", options->width, "Image width in pixels")->check(CLI::Range(1, 32768));
  command->add_option("--height", options->height, "Image height in pixels")->check(CLI::Range(1, 32768));
  command->add_option("--samples", options->samples, "Samples per pixel (a perfect square)")
      ->check(CLI::Range(1, 1024));
  command->add_option("--max-depth", options->maxDepth, "Reflection/refraction depth")->check(CLI::Range(0, 64));
  command->add_option("--shading", options->shading, "Shading for every mesh: flat, gouraud or phong")
      ->check(CLI::IsMember({"flat", "gouraud", "phong"}));
  command->add_option("--accel", options->accel, "Accelerator: kdtree-sah (default), kdtree-median or naive")
      ->check(CLI::IsMember({"kdtree-sah", "kdtree-median", "naive"}));
  command->add_option("--threads", options->threads, "Worker threads (default: all cores)")->check(CLI::Range(0, 1024));
  command->add_option("--pixel", options->pixel, "Trace only pixel x,y and print its value (debugging)");
  command->add_flag("--srgb", options->srgb, "Encode the output with the sRGB curve instead of linear");
  command->add_flag("-q,--quiet", options->quiet, "No progress or summary on stderr");
  command->callback([options, &runner] { runner = [options] { return runRender(*options); }; });
}

}  // namespace lancer::cli
