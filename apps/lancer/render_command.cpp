// `lancer render SCENE.toml | MESH.msh`: load, build the accelerator, trace, write the image.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "command_distribution.hpp"
#include "commands.hpp"
#include "lancer/cluster/tile_parts.hpp"
#include "lancer/image/atomic_file.hpp"
#include "lancer/image/exr_io.hpp"
#include "lancer/image/frame_sequence.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/image_row_writer.hpp"
#include "lancer/image/legend.hpp"
#include "lancer/render/denoiser.hpp"
#include "lancer/render/progress_line.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/util/stopwatch.hpp"
#include "piped_output.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

// Which --aovs layers an EXR gets.
struct ExrLayerChoice {
  bool albedo = false, normal = false, depth = false;
  bool any() const { return albedo || normal || depth; }
};

// The --legend image: a bar 300 pixels tall, text 14 pixels (the em).
constexpr int kLegendBarLength = 300;
constexpr float kLegendTextHeight = 14;

struct RenderCommandOptions {
  std::string input;                // the scene or mesh (takeMeshInput)
  std::vector<std::string> inputs;  // as given: the input, then views
  std::string output;
  std::string pixel;
  std::string legendFile;                          // --legend-file: the legends of the field-coloured meshes
  std::string legendFileOption = "--legend-file";  // or "--legend", as the command line spelled it
  std::string shard;                  // --shard I/N or auto: a job-array task's part of the image
  std::string aovs;                   // --aovs albedo,normal,depth: layers of an EXR output
  std::optional<double> progressive;  // --progressive SECONDS: rewrite the image at least this often
  SceneOverrides overrides;
};

int tracePixel(const PreparedRender& prepared, const Renderer& renderer, const std::string& pixel) {
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

// -o, else render.output, else the input's name as a .png in the current folder.
std::string outputPath(const RenderCommandOptions& options, const RenderSettings& settings) {
  if (!options.output.empty()) return options.output;
  return settings.output.empty() ? outputNamedAfter(options.input, ".png") : settings.output;
}

// -o -: what cannot go to stdout is refused before anything is read.
void checkPipedOutput(const RenderCommandOptions& options) {
  const char* refused = !options.shard.empty()   ? "--shard writes a part file per task"
                        : options.progressive    ? "--progressive rewrites its file as the picture converges"
                        : !options.aovs.empty()  ? "--aovs needs an .exr file"
                        : !options.pixel.empty() ? "--pixel prints its value to stdout"
                                                 : nullptr;
  if (refused)
    throw InputError(SourceLocation{"-o"},
                     fmt::format("-o - sends one PNG to stdout: {}; give -o FILE instead", refused));
}

// PNG, BMP and PPM go to the file band by band as they finish, so memory holds a few bands of rows
// whatever the image size; a GIF needs every pixel for its palette, an EXR is written whole, and the
// denoiser filters the whole image.
bool streamsToFile(const std::string& output, const RenderSettings& settings) {
  return !output.empty() && !settings.denoise && ImageRowWriter::streams(imageFormatFromPath(output));
}

bool isExr(const std::string& output) { return imageFormatFromPath(output) == ImageFormat::Exr; }

// --aovs: a comma-separated subset of albedo, normal, depth; only an EXR holds them.
ExrLayerChoice parseAovs(const std::string& aovs, const std::string& output) {
  ExrLayerChoice choice;
  if (aovs.empty()) return choice;
  if (!isExr(output))
    throw InputError(
        SourceLocation{"--aovs"},
        fmt::format("{} cannot hold albedo, normal or depth layers: write an .exr (-o NAME.exr)", output));
  std::size_t start = 0;
  while (start <= aovs.size()) {
    const std::size_t comma = std::min(aovs.find(',', start), aovs.size());
    const std::string name = aovs.substr(start, comma - start);
    if (name == "albedo")
      choice.albedo = true;
    else if (name == "normal")
      choice.normal = true;
    else if (name == "depth")
      choice.depth = true;
    else
      throw InputError(
          SourceLocation{"--aovs"},
          fmt::format("unknown layer '{}': use albedo, normal and depth, separated by commas", name));
    start = comma + 1;
  }
  return choice;
}

// The finished image into `output`: an EXR takes the radiance (and the chosen layers), the other
// formats the display image (exposure, tone curve) encoded as the settings say.
void writeFinal(const std::string& output, const Image& radiance, const RenderSettings& settings,
                const ExrLayerChoice& aovs, const FeatureBuffers* features) {
  if (!isExr(output)) {
    writeImage(output, displayImage(radiance, settings), imageWriteOptions(settings));
    return;
  }
  ExrLayers layers;
  if (features != nullptr) {
    if (aovs.albedo) layers.albedo = features->albedo;
    if (aovs.normal) layers.normal = features->normal;
    if (aovs.depth) layers.depth = features->depth;
  }
  writeExr(output, radiance, layers);
}

// The rendered radiance with the scene's legends drawn in, written as writeFinal writes it: what a
// plain render and each --progressive pass leave in `output`.
void writeWithLegends(const std::string& output, Image radiance, const PreparedRender& prepared,
                      const ExrLayerChoice& aovs, const FeatureBuffers* features) {
  const RenderSettings& settings = prepared.description.render;
  if (const std::optional<FieldColors>& fields = prepared.scene.fieldColors)
    drawLegends(radiance, fields->legends, fields->legendPlacement, settings.srgb);
  writeFinal(output, radiance, settings, aovs, features);
}

// Renders into `output` (atomically: an interrupted or failed render leaves any existing file as it
// was). Returns false when interrupted.
bool renderToFile(const PreparedRender& prepared, const Renderer& renderer, const std::string& output,
                  const ExrLayerChoice& aovs, const RenderOptions& renderOptions, RenderStats& stats) {
  const RenderSettings& settings = prepared.description.render;
  const ImageWriteOptions writeOptions = imageWriteOptions(settings);
  const bool cancellable = renderOptions.cancel != nullptr;
  // Legends are drawn over the whole picture, so a picture with legends is not streamed.
  const std::optional<FieldColors>& fields = prepared.scene.fieldColors;
  const bool legends = fields && fields->legendPlacement != LegendPlacement::None;
  if (!streamsToFile(output, settings) || legends) {
    FeatureBuffers features;
    Image image = renderer.renderFinal(renderOptions, &stats, aovs.any() ? &features : nullptr);
    if (stats.cancelled || (cancellable && renderOptions.cancel->load())) return false;
    writeWithLegends(output, std::move(image), prepared, aovs, aovs.any() ? &features : nullptr);
    return true;
  }
  ImageRowWriter writer(output, settings.width, settings.height, writeOptions);  // a bad folder fails now
  const bool toneMapped = settings.toneMap != ToneMap::None || settings.exposure != 0.0f;
  renderer.renderBands(
      renderOptions,
      [&](int, const Image& band) { writer.writeRows(toneMapped ? displayImage(band, settings) : band); },
      &stats);
  if (stats.cancelled || (cancellable && renderOptions.cancel->load())) return false;  // ~writer discards
  writer.commit();
  return true;
}

// --progressive: passes of 1, 2, 4, ... samples per pixel up to the scene's, each a whole image of
// its own (per-pixel sample streams: the last pass is the image a plain render gives), written
// (atomically) whenever `seconds` have passed since the last write, and at the end, each through
// the plain render's pipeline: the denoiser with the pass's feature buffers (as a plain render's),
// the legends, the tone curve and encoding, or the EXR with its layers. False when interrupted;
// the file then holds the last pass written, whose samples per pixel go to `writtenSamples` (0: none).
bool renderProgressive(const PreparedRender& prepared, const Renderer& finalRenderer,
                       const std::string& output, double seconds, const ExrLayerChoice& aovs,
                       const RenderOptions& renderOptions, RenderStats& stats, int& writtenSamples) {
  const RenderSettings& settings = prepared.description.render;
  // The features come from each pass's own samples where the integrator reports them (the last
  // pass's are then the plain render's), else from one primary-ray pass made before the first.
  const bool wanted = settings.denoise || aovs.any();
  const bool fromSamples = wanted && finalRenderer.featuresFromSamples();
  std::optional<FeatureBuffers> features;
  if (wanted && !fromSamples) features = finalRenderer.renderFeatures(renderOptions.threads);
  RenderSettings pass = settings;
  Stopwatch sinceWrite;
  for (int samples = 1;; samples = std::min(2 * samples, settings.samples)) {
    pass.samples = samples;
    const Renderer renderer(prepared.scene, prepared.accelerator, prepared.camera, pass);
    RenderStats passStats;
    RenderOptions passOptions = renderOptions;
    if (fromSamples) passOptions.features = &features.emplace(settings.width, settings.height);
    Image image = renderer.renderImage(passOptions, &passStats);
    stats.rays += passStats.rays;
    stats.seconds += passStats.seconds;
    stats.samplesPerPixel = passStats.samplesPerPixel;
    if (passStats.cancelled) return false;
    const bool last = samples >= settings.samples;
    if (last || sinceWrite.seconds() >= seconds) {
      if (settings.denoise) {
        DenoiseOptions denoiseOptions;
        denoiseOptions.threads = renderOptions.threads;
        image = denoise(image, *features, denoiseOptions);
      }
      writeWithLegends(output, std::move(image), prepared, aovs, features ? &*features : nullptr);
      writtenSamples = samples;
      sinceWrite = Stopwatch();
    }
    if (last) return true;
  }
}

// The part of the picture's legends in `rows`, the picture's rows from firstRow on: a task or a rank
// draws its share, so the assembled picture is the one a single render draws.
void drawLegendParts(const PreparedRender& prepared, Image& rows, int firstRow) {
  const std::optional<FieldColors>& fields = prepared.scene.fieldColors;
  const RenderSettings& settings = prepared.description.render;
  if (fields)
    drawLegendsInRows(rows, fields->legends, fields->legendPlacement, settings.srgb, settings.width,
                      settings.height, firstRow);
}

// Renders the band items of a job-array task into its part file (atomically); false when interrupted.
bool renderPart(const PreparedRender& prepared, const Renderer& renderer, const std::string& output,
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
    Image rows = renderer.renderRows(items.item(item), renderOptions, &itemStats);
    stats.rays += itemStats.rays;
    stats.seconds += itemStats.seconds;
    if (itemStats.cancelled) return false;  // ~part removes the temporary file
    drawLegendParts(prepared, rows, items.item(item).first * kTileSize);
    part.writeItem(displayImage(rows, settings));
  }
  part.commit();
  return true;
}

// The ranks of an MPI job share the band items; rank 0 writes them in order as they come (a few items
// in memory at once for a streamed format). False when interrupted.
bool renderDistributed(const PreparedRender& prepared, const Renderer& renderer, const std::string& output,
                       WorkDistribution& distribution, const RenderOptions& renderOptions,
                       RenderStats& stats) {
  const RenderSettings& settings = prepared.description.render;
  const ImageWriteOptions writeOptions = imageWriteOptions(settings);
  const BandItems items = bandItems(settings.width, settings.height, distribution.ranks());
  std::optional<ImageRowWriter> writer;
  Image whole;
  if (distribution.delivers()) {
    if (streamsToFile(output, settings))
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
    drawLegendParts(prepared, rows, items.item(item).first * kTileSize);
    return rows;
  };
  work.deliver = [&](int item, const Image& rows) {
    if (writer)
      writer->writeRows(displayImage(rows, settings));
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
    writeFinal(output, whole, settings, {}, nullptr);
  return true;
}

int runRender(const RenderCommandOptions& given) {
  const Stopwatch stopwatch;
  // -o -: rendered into a temporary PNG, sent to stdout once complete.
  std::optional<PipedOutput> piped;
  RenderCommandOptions options = given;
  if (given.output == "-") {
    checkPipedOutput(given);
    options.output = piped.emplace().path();
  }
  if (options.progressive && !(std::isfinite(*options.progressive) && *options.progressive > 0))
    throw InputError(SourceLocation{"--progressive"},
                     fmt::format("{} is not a number of seconds > 0 (how often the image is rewritten as it "
                                 "converges, e.g. 2)",
                                 *options.progressive));
  const std::unique_ptr<WorkDistribution> distribution = commandDistribution(!options.shard.empty());
  std::optional<ScheduledShard> shard;
  if (!options.shard.empty()) shard = resolveShard(options.shard, processEnvironment());
  const PreparedRender prepared =
      prepareScene(options.input, options.overrides, [&](const RenderSettings& s) {
        return streamsToFile(outputPath(options, s), s) ? ImageBuffer::Bands : ImageBuffer::Whole;
      });
  const RenderSettings& settings = prepared.description.render;
  const std::string output = outputPath(options, settings);
  const std::string shownOutput = piped ? "stdout" : output;  // for messages
  ExrLayerChoice aovs;
  if (options.pixel.empty()) {  // refuse a bad extension, bit depth or layer before rendering
    checkTransparentOutput(options.overrides, output);
    requireBitDepth(output, imageFormatFromPath(output), settings.bitDepth);
    requireImageSize(output, imageFormatFromPath(output), settings.width, settings.height);
    if (isExr(output) && !exrSupported()) writeExr(output, Image(1, 1));  // says how to get OpenEXR
    aovs = parseAovs(options.aovs, output);
  }
  if (shard && (settings.denoise || isExr(output) || settings.bitDepth != 8))
    throw InputError(SourceLocation{"--shard"},
                     "a job-array part holds 8-bit rows: --denoise, --bit-depth 16 and .exr need a render "
                     "without --shard");
  if (distribution->ranks() > 1 && (settings.denoise || !options.aovs.empty()))
    throw InputError(SourceLocation{options.input},
                     "--denoise and --aovs need the whole image in one process: run without mpirun");
  if (options.progressive && settings.integrator == IntegratorKind::Whitted)
    throw InputError(SourceLocation{"--progressive"},
                     "--progressive refines the samples of integrator = \"path\" or \"ao\"; this render uses "
                     "the Whitted model (add --integrator path)");
  if (options.progressive && (shard || distribution->ranks() > 1))
    throw InputError(SourceLocation{"--progressive"},
                     "--progressive writes one image from one process; "
                     "leave it out of --shard and MPI runs");
  // The legends are the same in every task of a job array (the scene's ranges): the first writes them.
  const bool writesLegend = !options.legendFile.empty() && options.pixel.empty() &&
                            (shard ? shard->shard.index == 0 : distribution->delivers());
  // The legend sheet goes with the picture: written beside its target under a hidden name before the
  // render, renamed into place once the picture is, removed when the render fails or is interrupted.
  StagedFrames legend;
  if (!options.legendFile.empty()) {
    imageFormatFromPath(options.legendFile);
    if (!prepared.scene.fieldColors)
      throw InputError(
          SourceLocation{options.input},
          fmt::format(
              "{} needs a mesh coloured by a field (--color-by FIELD, or color_by = {{ field = \"...\" }} "
              "in a [[mesh]])",
              options.legendFileOption));
    if (options.pixel.empty() && sameOutputPath(options.legendFile, output))
      throw InputError(SourceLocation{options.legendFileOption},
                       fmt::format("'{}' is also the picture's output: give the legend a name of its own",
                                   options.legendFile));
  }
  if (writesLegend) {
    // Before the render, so that a failed command changes no file: the legend's folder, its text (the
    // font) and its bytes. The bar holds the map's display values: written as they are, like the
    // picture's.
    requireWritable(options.legendFile);  // the error names the legend, not its hidden name
    legend.write(
        options.legendFile,
        legendSheet(prepared.scene.fieldColors->legends, kLegendBarLength, kLegendTextHeight, settings.srgb),
        ImageWriteOptions{});
  }

  const Renderer renderer = prepared.renderer();
  if (!options.pixel.empty()) return tracePixel(prepared, renderer, options.pixel);

  RenderOptions renderOptions = commandRenderOptions(options.overrides);
  renderOptions.threads = commandThreads(options.overrides.threads, *distribution);
  const bool talks = distribution->delivers();  // rank 0 of an MPI job, or a single process
  const bool progress = talks && showProgress(options.overrides);
  if (progress) renderOptions.onProgress = printProgressLine;
  RenderStats stats;
  bool written = false;
  int progressiveSamples = 0;  // of the last pass --progressive wrote
  try {
    if (shard)
      written = renderPart(prepared, renderer, output, *shard, renderOptions, options.overrides.quiet, stats);
    else if (distribution->ranks() > 1)
      written = renderDistributed(prepared, renderer, output, *distribution, renderOptions, stats);
    else if (options.progressive)
      written = renderProgressive(prepared, renderer, output, *options.progressive, aovs, renderOptions,
                                  stats, progressiveSamples);
    else
      written = renderToFile(prepared, renderer, output, aovs, renderOptions, stats);
  } catch (const NonFiniteRenderError& e) {
    if (progress) std::fputc('\n', stderr);
    throw InputError(SourceLocation{options.input}, e.what());
  } catch (...) {
    if (progress) std::fputc('\n', stderr);  // the error goes below the progress line
    throw;
  }
  if (progress) std::fputc('\n', stderr);
  if (!written && progressiveSamples > 0) {
    std::fprintf(stderr, "lancer: interrupted; %s holds the last pass written, %d samples per pixel of %d\n",
                 shownOutput.c_str(), progressiveSamples, settings.samples);
    return kExitInterrupted;
  }
  if (!written) return talks ? interruptedExit(shownOutput) : kExitInterrupted;  // rank 0 alone says so
  legend.publish();
  if (piped && talks) piped->send();
  if (!talks || shard) return kExitOk;
  if (!options.overrides.quiet) {
    const double total = stopwatch.seconds();
    std::fprintf(stderr,
                 "%s: %dx%d, %zu faces, %.2f samples/pixel, load %.3f s, build %.3f s, trace %.3f s "
                 "(%.2f Mrays/s), total %.3f s\n",
                 shownOutput.c_str(), settings.width, settings.height, prepared.scene.geometry.faces.size(),
                 stats.samplesPerPixel, prepared.loadSeconds, prepared.buildSeconds, stats.seconds,
                 stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0, total);
  }
  if (options.overrides.timings) std::fprintf(stderr, "%s\n", formatStageTimes(prepared.stages).c_str());
  return kExitOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command = app.add_subcommand("render",
                                         "Render a scene file (.toml), or a mesh (.msh, or .pos views) with "
                                         "an automatic camera, lights and colours");
  addInputOption(*command, options->inputs);
  addSceneViewOptions(*command, options->overrides);
  command
      ->add_option(
          "-o,--output", options->output,
          fmt::format("Output image ({}; default: render.output, else the input's name as a .png in the "
                      "current folder); - writes a PNG to stdout",
                      kImageExtensions))
      ->group(kOutputGroup);
  addSceneOutputOptions(*command, options->overrides);
  command
      ->add_option("--legend-file", options->legendFile,
                   "Also write the legends of the field-coloured meshes (color_by) to this image")
      ->group(kOutputGroup);
  command
      ->add_option("--aovs", options->aovs,
                   "Layers of an .exr output beside the radiance: albedo, normal, depth (comma-separated)")
      ->group(kOutputGroup);
  command->add_option("--pixel", options->pixel, "Trace only pixel x,y and print its value (debugging)")
      ->group(kOutputGroup);
  command
      ->add_option(
          "--progressive", options->progressive,
          "path, ao: render 1, 2, 4, ... samples per pixel up to the scene's, rewriting the image at "
          "least every SECONDS as it converges")
      ->group(kOutputGroup);
  command
      ->add_option("--shard", options->shard,
                   "Job arrays: render task I of N's bands into OUTPUT.part-I-of-N (I/N, or auto from SLURM "
                   "or mpirun); `lancer assemble --tiles` stitches the parts")
      ->group(kClusterGroup);
  command->callback([options, &runner] {
    // --legend FILE.png, the older spelling of --legend-file: a file name with an extension.
    std::string& legend = options->overrides.legend;
    if (!enumFromName<LegendPlacement>(kLegendPlacementNames, legend) &&
        std::filesystem::path(legend).has_extension()) {
      if (!options->legendFile.empty())
        throw CLI::ValidationError("--legend", "'" + legend + "' is not right, bottom or none");
      options->legendFile = std::exchange(legend, std::string());
      options->legendFileOption = "--legend";
    }
    takeInputFromGmshView(options->inputs, options->overrides);
    runner = [options] {
      options->input = takeMeshInput(options->inputs, options->overrides.views);
      return runRender(*options);
    };
  });
}

}  // namespace lancer::cli
