// `lancer assemble 'frames/%04d.png' -o turntable.gif`: the animation from numbered frames that job-array
// tasks rendered (`lancer animate --shard`), byte-identical to `lancer animate -o turntable.gif`; and
// `lancer assemble --tiles poster.png.part-* -o poster.png`: a still from the parts of `render --shard`.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "lancer/cluster/tile_parts.hpp"
#include "lancer/image/animation_writer.hpp"
#include "lancer/image/frame_sequence.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/setting_checks.hpp"
#include "lancer/util/input_error.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

struct AssembleCommandOptions {
  std::vector<std::string> inputs;
  std::string output;
  bool tiles = false;
  std::optional<int> frames;
  std::optional<double> fps;
  AnimationOutputOptions writer;
  bool quiet = false;
};

// The number of the frame file `name` (in the pattern's folder), or -1 when it is not one.
int frameNumber(const FramePattern& pattern, const std::string& name) {
  const std::string prefix = std::filesystem::path(pattern.prefix + "0").filename().string();
  const std::string head = prefix.substr(0, prefix.size() - 1);
  if (name.size() <= head.size() + pattern.suffix.size() || name.rfind(head, 0) != 0 ||
      name.compare(name.size() - pattern.suffix.size(), pattern.suffix.size(), pattern.suffix) != 0)
    return -1;
  const std::string digits = name.substr(head.size(), name.size() - head.size() - pattern.suffix.size());
  if (digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return -1;
  const int number = std::stoi(digits);
  return std::filesystem::path(pattern.name(number)).filename().string() == name ? number : -1;
}

// How many frames the pattern names: --frames, else one past the highest number on disk. Every frame
// 0..count-1 must exist.
int countFrames(const FramePattern& pattern, const std::string& text, std::optional<int> frames) {
  int count = frames.value_or(0);
  if (!frames) {
    const std::filesystem::path folder = std::filesystem::path(pattern.name(0)).parent_path();
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, error))
      count = std::max(count, frameNumber(pattern, entry.path().filename().string()) + 1);
    if (count == 0)
      throw InputError(SourceLocation{text},
                       fmt::format("no frames: there is no {} (nor any other number)", pattern.name(0)));
  }
  for (int k = 0; k < count; ++k)
    if (!std::filesystem::exists(pattern.name(k)))
      throw InputError(SourceLocation{pattern.name(k)},
                       fmt::format("frame {} of {} is missing; render it with `lancer animate ... "
                                   "--frame-range {}-{}` (or --skip-existing to fill every gap)",
                                   k, count, k, k));
  return count;
}

int assembleFrames(const AssembleCommandOptions& options) {
  if (options.inputs.size() != 1)
    throw InputError(SourceLocation{"assemble"},
                     "give one frame pattern such as 'frames/%04d.png' (quoted), or --tiles with part files");
  const std::string& text = options.inputs.front();
  const std::optional<FramePattern> pattern = parseFramePattern(text);
  if (!pattern)
    throw InputError(SourceLocation{text},
                     "the frames need a pattern with %d or %04d, e.g. 'frames/%04d.png'");
  if (imageFormatFromPath(pattern->name(0)) != ImageFormat::Png)
    throw InputError(SourceLocation{text}, "assemble reads PNG frames (render them as frame_%04d.png)");
  if (parseFramePattern(options.output))
    throw InputError(SourceLocation{options.output}, "assemble writes an animated .gif or .png, not frames");
  const int count = countFrames(*pattern, text, options.frames);

  PngDescription first;
  Image frame = readPng(pattern->name(0), TransferCurve::Linear, &first);
  const int width = frame.width(), height = frame.height();
  AnimationOutputOptions format = options.writer;
  format.frames = count;
  format.fps = options.fps ? checkFps(*options.fps, SettingName{SourceLocation{"--fps"}, "--fps"})
                           : AnimationSettings{}.fps;
  if (format.loop) checkLoop(*format.loop, SettingName{SourceLocation{"--loop"}, "--loop"});
  // The frames' 8-bit values go through unchanged when decoded and encoded with the same curve, so
  // the writer sees what `lancer animate` handed it after encoding.
  format.still.curve = first.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  format.still.alpha = first.alpha ? AlphaChannel::Always : AlphaChannel::Never;
  format.transparentBackground = first.alpha;
  format.still.metadata = commandProvenance();
  AnimationWriter out(options.output, width, height, format);
  if (!options.quiet && !out.frameRateNote().empty())
    std::fprintf(stderr, "%s\n", out.frameRateNote().c_str());
  for (int k = 0; k < count; ++k) {
    PngDescription description;
    frame = readPng(pattern->name(k), format.still.curve, &description);
    if (frame.width() != width || frame.height() != height || description.alpha != first.alpha ||
        description.srgb != first.srgb)
      throw InputError(
          SourceLocation{pattern->name(k)},
          fmt::format("frame {} is {}x{}{}{}, but frame 0 is {}x{}{}{}: not from the same animation", k,
                      frame.width(), frame.height(), description.alpha ? " with alpha" : "",
                      description.srgb ? " sRGB" : "", width, height, first.alpha ? " with alpha" : "",
                      first.srgb ? " sRGB" : ""));
    out.addFrame(k, frame);
  }
  out.finish();
  if (!options.quiet)
    std::fprintf(stderr, "%s: %d frames %dx%d assembled\n", options.output.c_str(), count, width, height);
  return kExitOk;
}

int runAssemble(const AssembleCommandOptions& options) {
  if (!options.tiles) return assembleFrames(options);
  if (options.frames || options.fps || options.writer.loop || !options.writer.dither.empty() ||
      !options.writer.palette.empty())
    throw InputError(
        SourceLocation{"--tiles"},
        "--tiles stitches a still: --frames, --fps, --loop, --dither and --palette do not apply");
  assembleTileParts(options.inputs, options.output, commandProvenance());
  if (!options.quiet)
    std::fprintf(stderr, "%s: assembled from %zu parts\n", options.output.c_str(), options.inputs.size());
  return kExitOk;
}

}  // namespace

void addAssembleCommand(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<AssembleCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "assemble",
      "Make the animation from numbered frames (job arrays: animate --shard), or with --tiles the still "
      "from the part files of render --shard");
  command->add_option("inputs", options->inputs, "'frames/%04d.png' (quoted), or with --tiles the part files")
      ->required();
  command
      ->add_option("-o,--output", options->output,
                   "Output: NAME.gif, NAME.png (animated), NAME.mp4 or NAME.webm; a still with --tiles")
      ->required();
  command->add_flag("--tiles", options->tiles,
                    "Stitch the parts of `lancer render --shard I/N` into the image");
  command->add_option("--frames", options->frames, "Number of frames (default: up to the highest on disk)")
      ->check(CLI::Range(1, kMaxFrames));
  command->add_option(
      "--fps", options->fps,
      fmt::format("Frames per second ({:g} to {:g}; default 12, as animate's)", kMinFps, kMaxFps));
  addAnimationWriterOptions(*command, options->writer);
  command->add_flag("-q,--quiet", options->quiet, "No summary on stderr");
  command->callback([options, &runner] { runner = [options] { return runAssemble(*options); }; });
}

}  // namespace lancer::cli
