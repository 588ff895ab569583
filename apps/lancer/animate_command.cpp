// `lancer animate SCENE.toml -o turntable.gif`: the camera or a light orbits the scene; one
// accelerator build serves every frame. Output: an animated GIF, or numbered still frames.
#include <fmt/format.h>

#include <cstdio>
#include <optional>

#include "commands.hpp"
#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/render/animation.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

struct AnimateCommandOptions {
  std::string input;
  std::string output;
  std::optional<int> frames;
  std::optional<double> fps;
  std::string orbit;
  int loop = kGifLoopForever;
  std::string dither = "ordered";
  std::string palette = "global";
  SceneOverrides overrides;
};

// A frame-sequence name such as "frames/turn_%04d.png": exactly one %d (optionally %0Nd), no other %.
struct FramePattern {
  std::string prefix, suffix;
  int width = 0;

  std::string name(int frame) const { return fmt::format("{}{:0{}d}{}", prefix, frame, width, suffix); }
};

std::optional<FramePattern> parseFramePattern(const std::string& path) {
  const std::size_t percent = path.find('%');
  if (percent == std::string::npos) return std::nullopt;
  FramePattern pattern;
  pattern.prefix = path.substr(0, percent);
  std::size_t i = percent + 1;
  std::size_t digitsStart = i;
  while (i < path.size() && std::isdigit(static_cast<unsigned char>(path[i]))) ++i;
  if (i >= path.size() || path[i] != 'd' || (i > digitsStart && path[digitsStart] != '0') || i - digitsStart > 2)
    throw InputError(SourceLocation{path}, "a frame-sequence name needs one %d or %0Nd (e.g. frame_%04d.png)");
  if (i > digitsStart) pattern.width = std::stoi(path.substr(digitsStart, i - digitsStart));
  pattern.suffix = path.substr(i + 1);
  if (pattern.suffix.find('%') != std::string::npos)
    throw InputError(SourceLocation{path}, "a frame-sequence name may hold only one %d");
  return pattern;
}

int parseOrbit(const std::string& orbit, std::size_t lightCount) {
  if (orbit == "camera") return -1;
  int light = -1;
  char trailing = 0;
  if (std::sscanf(orbit.c_str(), "light:%d%c", &light, &trailing) == 1 && light >= 0 &&
      static_cast<std::size_t>(light) < lightCount)
    return light;
  throw InputError(SourceLocation{"--orbit"},
                   fmt::format("'{}' is not an orbit: use 'camera' or 'light:K' with K from 0 to {} (the scene has "
                               "{} light{})",
                               orbit, lightCount == 0 ? 0 : lightCount - 1, lightCount, lightCount == 1 ? "" : "s"));
}

int runAnimate(const AnimateCommandOptions& options) {
  PreparedScene prepared = prepareScene(options.input, options.overrides);
  const RenderSettings& settings = prepared.description.render;
  AnimationSettings animation = prepared.description.animation.value_or(AnimationSettings{});
  if (options.frames) animation.frames = *options.frames;
  if (options.fps) animation.fps = *options.fps;
  if (!options.orbit.empty()) animation.orbitLight = parseOrbit(options.orbit, prepared.scene.lights.size());

  const std::string output = options.output.empty() ? settings.output : options.output;
  if (output.empty()) throw InputError(SourceLocation{options.input}, "no output: give -o FILE.gif or -o frame_%04d.png");
  const std::optional<FramePattern> pattern = parseFramePattern(output);
  ImageWriteOptions stillOptions;
  stillOptions.curve = settings.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  stillOptions.alpha = settings.transparentBackground ? AlphaChannel::Always : AlphaChannel::Never;
  std::optional<GifWriter> gif;
  if (pattern) {
    imageFormatFromPath(pattern->name(0));
  } else {
    if (imageFormatFromPath(output) != ImageFormat::Gif)
      throw InputError(SourceLocation{output},
                       "an animation is written as .gif, or as numbered frames with %04d in the name (frame_%04d.png)");
    GifOptions gifOptions;
    gifOptions.fps = animation.fps;
    gifOptions.loopCount = options.loop;
    gifOptions.curve = stillOptions.curve;
    gifOptions.palette = options.palette == "per-frame" ? GifPalette::PerFrame : GifPalette::Global;
    gifOptions.dither = options.dither == "none" ? Dither::None
                                                 : (options.dither == "floyd-steinberg" ? Dither::FloydSteinberg
                                                                                        : Dither::Ordered);
    gif.emplace(output, settings.width, settings.height, gifOptions);  // fails now on a bad folder
    if (!options.overrides.quiet && std::abs(gifActualFrameRate(animation.fps) - animation.fps) > 1e-9)
      std::fprintf(stderr, "lancer: GIF delays are in 1/100 s: %g fps plays at %.4g fps\n", animation.fps,
                   gifActualFrameRate(animation.fps));
  }

  const std::atomic<bool>& interrupted = installInterruptHandler();
  RenderOptions renderOptions;
  renderOptions.threads = options.overrides.threads;
  renderOptions.cancel = &interrupted;
  const bool progress = showProgress(options.overrides);
  auto onProgress = [&](const AnimationProgress& p) {
    const double done = (p.frame + p.frameProgress.fraction) / p.frames;
    const double eta = done > 0 ? p.seconds * (1 - done) / done : 0;
    std::fprintf(stderr, "\r  frame %d/%d  %5.1f%%  %7.2f Mrays/s  ETA %6.1f s ", p.frame + 1, p.frames, 100 * done,
                 p.frameProgress.seconds > 0 ? p.frameProgress.rays / p.frameProgress.seconds * 1e-6 : 0.0, eta);
    std::fflush(stderr);
  };
  const AnimationStats stats = renderAnimation(
      prepared.scene, prepared.accelerator, prepared.description, animation, renderOptions,
      [&](int frame, const Image& image) {
        if (gif) {
          gif->addFrame(image);
        } else {
          writeImage(pattern->name(frame), image, stillOptions);
        }
      },
      progress ? std::function<void(const AnimationProgress&)>(onProgress) : nullptr);
  if (progress) std::fputc('\n', stderr);
  if (stats.cancelled) {
    std::fprintf(stderr, "lancer: interrupted; %s was not written\n", gif ? output.c_str() : "no further frame");
    return kExitInterrupted;
  }
  if (gif) gif->finish();
  if (!options.overrides.quiet) {
    std::fprintf(stderr,
                 "%s: %d frames %dx%d, %zu faces, load %.3f s, build %.3f s (once), frames %.3f s "
                 "(%.3f s/frame, %.2f Mrays/s)\n",
                 output.c_str(), animation.frames, settings.width, settings.height, prepared.scene.faces.size(),
                 prepared.loadSeconds, prepared.buildSeconds, stats.seconds, stats.seconds / animation.frames,
                 stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0);
  }
  return kExitOk;
}

}  // namespace

void addAnimateCommand(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<AnimateCommandOptions>();
  CLI::App* command =
      app.add_subcommand("animate", "Render an orbit of the camera or of a light as an animated GIF or numbered frames");
  command->add_option("input", options->input, "Scene file (.toml) or gmsh mesh (.msh)")->required();
  command->add_option("-o,--output", options->output,
                      "Output: NAME.gif (animated, looping) or NAME_%04d.png/.bmp/.ppm (one file per frame)");
  command->add_option("--frames", options->frames, "Number of frames")->check(CLI::Range(1, 10000));
  command->add_option("--fps", options->fps, "Frames per second")->check(CLI::Range(0.01, 100.0));
  command->add_option("--orbit", options->orbit, "What turns: camera or light:K");
  command->add_option("--loop", options->loop, "GIF repeat count: 0 forever (default), -1 play once")
      ->check(CLI::Range(-1, 65535));
  command->add_option("--dither", options->dither, "GIF dithering: ordered (default), floyd-steinberg or none")
      ->check(CLI::IsMember({"none", "ordered", "floyd-steinberg"}));
  command->add_option("--palette", options->palette, "GIF palette: global (default, no flicker) or per-frame")
      ->check(CLI::IsMember({"global", "per-frame"}));
  addSceneOverrideOptions(*command, options->overrides);
  command->callback([options, &runner] { runner = [options] { return runAnimate(*options); }; });
}

}  // namespace lancer::cli
