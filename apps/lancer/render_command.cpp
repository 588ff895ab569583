// `lancer render SCENE.toml | MESH.msh`: load, build the accelerator, trace, write the image.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "command_distribution.hpp"
#include "commands.hpp"
#include "lancer/cluster/tile_parts.hpp"
#include "lancer/image/color_map.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/image_row_writer.hpp"
#include "lancer/render/progress_line.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/util/stopwatch.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

// The --legend image: a tall bar with room for the tick labels.
constexpr int kLegendWidth = 120;
constexpr int kLegendHeight = 320;

struct RenderCommandOptions {
  std::string input;
  std::string output;
  std::string pixel;
  std::string legend;      // --legend: colour bar of the first field-coloured mesh
  std::string shard;       // --shard I/N or auto: a job-array task's part of the image
  double progressive = 0;  // --progressive SECONDS: rewrite the image at least this often as it converges
  SceneOverrides overrides;
};

int tracePixel(const PreparedScene& prepared, const Renderer& renderer, const std::string& pixel) {
  const RenderSettings& settings = prepared.description.render;
  int x = -1, y = -1;
  char trailing = 0;
  if (std::sscanf(pixel.c_str(), "%d,%d%c", &x, &y, &trailing) != 2 || x < 0 || y < 0 ||
      x >= settings.width || y >= settings.height)
    throw InputError(SourceLocation{"--pixel"}, fmt::format("'{}' is not a pixel 'x,y' inside {}x{}", pixel,
                                                            settings.width, settings.height));
  TraceCounters counters;
  std::uint64_t samples = 0;
  const Rgba value = renderer.renderPixel(x, y, counters, samples);
  std::printf("pixel %d,%d: rgb %.6f %.6f %.6f alpha %.3f (%llu samples, %llu rays)\n", x, y, value.r,
              value.g, value.b, value.a, static_cast<unsigned long long>(samples),
              static_cast<unsigned long long>(counters.rays));
  return kExitOk;
}

std::string outputPath(const RenderCommandOptions& options, const RenderSettings& settings) {
  return options.output.empty() ? settings.output : options.output;
}

// PNG, BMP and PPM go to the file band by band as they finish, so memory holds a few bands of rows
// whatever the image size; a GIF needs every pixel for its palette.
bool streamsToFile(const std::string& output) {
  return !output.empty() && ImageRowWriter::streams(imageFormatFromPath(output));
}

// Renders into `output` (atomically: an interrupted or failed render leaves any existing file as it
// was). Returns false when interrupted.
bool renderToFile(const PreparedScene& prepared, const Renderer& renderer, const std::string& output,
                  const RenderOptions& renderOptions, RenderStats& stats) {
  const RenderSettings& settings = prepared.description.render;
  const ImageWriteOptions writeOptions = imageWriteOptions(settings);
  const bool cancellable = renderOptions.cancel != nullptr;
  if (!streamsToFile(output)) {
    const Image image = renderer.renderImage(renderOptions, &stats);
    if (cancellable && renderOptions.cancel->load()) return false;
    writeImage(output, image, writeOptions);
    return true;
  }
  ImageRowWriter writer(output, settings.width, settings.height, writeOptions);  // a bad folder fails now
  renderer.renderBands(
      renderOptions, [&](int, const Image& band) { writer.writeRows(band); }, &stats);
  if (stats.cancelled || (cancellable && renderOptions.cancel->load())) return false;  // ~writer discards
  writer.commit();
  return true;
}

// --progressive: passes of 1, 2, 4, ... samples per pixel up to the scene's, each a whole image of
// its own (per-pixel sample streams: the last pass is the image a plain render gives), written
// (atomically) whenever `seconds` have passed since the last write, and at the end. False when
// interrupted; the file then holds the last pass written.
bool renderProgressive(const PreparedScene& prepared, const Camera& camera, const std::string& output,
                       double seconds, const RenderOptions& renderOptions, RenderStats& stats) {
  const RenderSettings& settings = prepared.description.render;
  const ImageWriteOptions writeOptions = imageWriteOptions(settings);
  RenderSettings pass = settings;
  Stopwatch sinceWrite;
  for (int samples = 1;; samples = std::min(2 * samples, settings.samples)) {
    pass.samples = samples;
    const Renderer renderer(prepared.scene, prepared.accelerator, camera, pass);
    RenderStats passStats;
    const Image image = renderer.renderImage(renderOptions, &passStats);
    stats.rays += passStats.rays;
    stats.seconds += passStats.seconds;
    stats.samplesPerPixel = passStats.samplesPerPixel;
    if (passStats.cancelled) return false;
    const bool last = samples >= settings.samples;
    if (last || sinceWrite.seconds() >= seconds) {
      writeImage(output, image, writeOptions);
      sinceWrite = Stopwatch();
    }
    if (last) return true;
  }
}

// Renders the band items of a job-array task into its part file (atomically); false when interrupted.
bool renderPart(const PreparedScene& prepared, const Renderer& renderer, const std::string& output,
                const ScheduledShard& shard, const RenderOptions& renderOptions, bool quiet,
                RenderStats& stats) {
  const RenderSettings& settings = prepared.description.render;
  const ImageWriteOptions writeOptions = imageWriteOptions(settings);
  TilePartHeader header;
  header.width = settings.width;
  header.height = settings.height;
  header.shard = shard.shard;
  header.bandsPerItem = bandItems(settings.width, settings.height, shard.shard.count).bandsPerItem;
  header.curve = writeOptions.curve;
  header.alpha = writeOptions.alpha == AlphaChannel::Always;
  const BandItems items = bandItemsOf(settings.height, header.bandsPerItem);
  const std::vector<int> mine = tilePartItems(header);
  const std::string path = tilePartPath(output, shard.shard);
  if (!quiet)
    std::fprintf(stderr, "lancer: task %d of %d (%s) renders %zu of %d band items into %s\n",
                 shard.shard.index, shard.shard.count, shard.source.c_str(), mine.size(), items.itemCount,
                 path.c_str());
  TilePartWriter part(path, header);
  for (const int item : mine) {
    RenderStats itemStats;
    const Image rows = renderer.renderRows(items.item(item), renderOptions, &itemStats);
    stats.rays += itemStats.rays;
    stats.seconds += itemStats.seconds;
    if (itemStats.cancelled) return false;  // ~part removes the temporary file
    part.writeItem(rows);
  }
  part.commit();
  return true;
}

// The ranks of an MPI job share the band items; rank 0 writes them in order as they come (a few items
// in memory at once for a streamed format). False when interrupted.
bool renderDistributed(const PreparedScene& prepared, const Renderer& renderer, const std::string& output,
                       WorkDistribution& distribution, const RenderOptions& renderOptions,
                       RenderStats& stats) {
  const RenderSettings& settings = prepared.description.render;
  const ImageWriteOptions writeOptions = imageWriteOptions(settings);
  const BandItems items = bandItems(settings.width, settings.height, distribution.ranks());
  std::optional<ImageRowWriter> writer;
  Image whole;
  if (distribution.delivers()) {
    if (streamsToFile(output))
      writer.emplace(output, settings.width, settings.height, writeOptions);  // a bad folder fails now
    else
      whole = Image(settings.width, settings.height);
  }
  const Stopwatch stopwatch;
  DistributedWork work;
  work.itemCount = items.itemCount;
  work.window = 2 * distribution.ranks() + 2;
  work.cancel = renderOptions.cancel;
  work.render = [&](int item) {
    RenderStats itemStats;
    Image rows = renderer.renderRows(items.item(item), renderOptions, &itemStats);
    stats.rays += itemStats.rays;
    return rows;
  };
  work.deliver = [&](int item, const Image& rows) {
    if (writer)
      writer->writeRows(rows);
    else
      whole.pasteTile(rows, 0, items.item(item).first * kTileSize);
  };
  if (renderOptions.onProgress)
    work.onDelivered = [&](int done, int total) {
      RenderProgress progress;
      progress.fraction = static_cast<double>(done) / total;
      progress.seconds = stopwatch.seconds();
      renderOptions.onProgress(progress);
    };
  const bool finished = distribution.run(work);
  stats.seconds = stopwatch.seconds();
  stats.samplesPerPixel = settings.samples;
  if (!finished || !distribution.delivers()) return finished;
  if (writer)
    writer->commit();
  else
    writeImage(output, whole, writeOptions);
  return true;
}

int runRender(const RenderCommandOptions& options) {
  const Stopwatch stopwatch;
  const std::unique_ptr<WorkDistribution> distribution = commandDistribution(!options.shard.empty());
  std::optional<ScheduledShard> shard;
  if (!options.shard.empty()) shard = resolveShard(options.shard, processEnvironment());
  PreparedScene prepared = prepareScene(options.input, options.overrides, [&](const RenderSettings& s) {
    return streamsToFile(outputPath(options, s)) ? ImageBuffer::Bands : ImageBuffer::Whole;
  });
  const RenderSettings& settings = prepared.description.render;
  const std::string output = outputPath(options, settings);
  if (output.empty() && options.pixel.empty())
    throw InputError(SourceLocation{options.input}, "no output image: give -o FILE or set render.output");
  if (!output.empty()) imageFormatFromPath(output);  // refuse a bad extension before rendering
  if (options.progressive > 0 && settings.integrator == IntegratorKind::Whitted)
    throw InputError(SourceLocation{"--progressive"},
                     "--progressive refines the samples of integrator = \"path\" or \"ao\"; this render uses "
                     "the Whitted model (add --integrator path)");
  if (options.progressive > 0 && (shard || distribution->ranks() > 1))
    throw InputError(SourceLocation{"--progressive"},
                     "--progressive writes one image from one process; "
                     "leave it out of --shard and MPI runs");
  if (shard && !options.legend.empty())
    throw InputError(SourceLocation{"--legend"}, "--legend is written by a render without --shard");
  if (!options.legend.empty()) {
    imageFormatFromPath(options.legend);
    if (!prepared.scene.fieldColors)
      throw InputError(
          SourceLocation{options.input},
          "--legend needs a mesh coloured by a field (color_by = { field = \"...\" } in a [[mesh]])");
  }

  const Camera camera = makeCamera(prepared.description.camera, prepared.scene, settings);
  const Renderer renderer(prepared.scene, prepared.accelerator, camera, settings);
  if (!options.pixel.empty()) return tracePixel(prepared, renderer, options.pixel);

  RenderOptions renderOptions = commandRenderOptions(options.overrides);
  renderOptions.threads = commandThreads(options.overrides.threads, *distribution);
  const bool talks = distribution->delivers();  // rank 0 of an MPI job, or a single process
  const bool progress = talks && showProgress(options.overrides);
  if (progress) renderOptions.onProgress = printProgressLine;
  RenderStats stats;
  bool written = false;
  try {
    if (shard)
      written = renderPart(prepared, renderer, output, *shard, renderOptions, options.overrides.quiet, stats);
    else if (distribution->ranks() > 1)
      written = renderDistributed(prepared, renderer, output, *distribution, renderOptions, stats);
    else if (options.progressive > 0)
      written = renderProgressive(prepared, camera, output, options.progressive, renderOptions, stats);
    else
      written = renderToFile(prepared, renderer, output, renderOptions, stats);
  } catch (...) {
    if (progress) std::fputc('\n', stderr);  // the error goes below the progress line
    throw;
  }
  if (progress) std::fputc('\n', stderr);
  if (!written) return talks ? interruptedExit(output) : kExitInterrupted;  // rank 0 alone says so
  if (!talks || shard) return kExitOk;
  if (!options.legend.empty()) {
    // The bar holds the map's display values: written as they are, like the picture's field colours.
    const FieldColors::Legend& legend = prepared.scene.fieldColors->legend;
    writeImage(options.legend,
               colorBarImage(legend.map, legend.low, legend.high, kLegendWidth, kLegendHeight));
  }
  if (!options.overrides.quiet) {
    const double total = stopwatch.seconds();
    std::fprintf(stderr,
                 "%s: %dx%d, %zu faces, %.2f samples/pixel, load %.3f s, build %.3f s, trace %.3f s "
                 "(%.2f Mrays/s), total %.3f s\n",
                 output.c_str(), settings.width, settings.height, prepared.scene.geometry.faces.size(),
                 stats.samplesPerPixel, prepared.loadSeconds, prepared.buildSeconds, stats.seconds,
                 stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, total);
  }
  if (options.overrides.timings) std::fprintf(stderr, "%s\n", formatStageTimes(prepared.stages).c_str());
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
  command->add_option(
      "--shard", options->shard,
      "Job arrays: render task I of N's bands into OUTPUT.part-I-of-N (I/N, or auto from SLURM "
      "or mpirun); `lancer assemble --tiles` stitches the parts");
  addSceneOverrideOptions(*command, options->overrides);
  command->add_option("--legend", options->legend,
                      "Also write the colour bar of the first field-coloured mesh (color_by) to this image");
  command->add_option("--pixel", options->pixel, "Trace only pixel x,y and print its value (debugging)");
  command
      ->add_option(
          "--progressive", options->progressive,
          "path, ao: render 1, 2, 4, ... samples per pixel up to the scene's, rewriting the image at "
          "least every SECONDS as it converges")
      ->check(CLI::PositiveNumber);
  command->callback([options, &runner] { runner = [options] { return runRender(*options); }; });
}

}  // namespace lancer::cli
