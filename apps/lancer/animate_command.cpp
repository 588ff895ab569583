// `lancer animate SCENE.toml -o turntable.gif`: the camera or a light orbits the scene; one
// accelerator build serves every frame. Output: an animated GIF, an animated PNG, or numbered frames.
#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "commands.hpp"
#include "frame_sequence.hpp"
#include "lancer/image/apng_writer.hpp"
#include "lancer/image/atomic_file.hpp"
#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/render/animation.hpp"
#include "lancer/scene/render_limits.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

struct AnimateCommandOptions {
  std::string input;
  std::string output;
  std::optional<int> frames;
  std::optional<double> fps;
  std::string orbit;
  std::optional<int> loop;  // default: forever
  std::string dither;       // default: ordered
  std::string palette;      // default: global
  SceneOverrides overrides;
};

int parseOrbit(const std::string& orbit, std::size_t lightCount) {
  if (orbit == "camera") return -1;
  // "light:K" with K plain decimal digits, as the scene file's animation.orbit accepts.
  const std::string digits = orbit.rfind("light:", 0) == 0 ? orbit.substr(6) : std::string();
  const bool number = !digits.empty() && digits.size() <= 9 &&
                      std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (number && static_cast<std::size_t>(std::stoi(digits)) < lightCount) return std::stoi(digits);
  if (lightCount == 0)
    throw InputError(
        SourceLocation{"--orbit"},
        fmt::format("'{}' is not an orbit here: the scene has no [[light]]; use 'camera'", orbit));
  throw InputError(
      SourceLocation{"--orbit"},
      fmt::format("'{}' is not an orbit: use 'camera' or 'light:K' with K from 0 to {} (the scene has "
                  "{} light{})",
                  orbit, lightCount - 1, lightCount, lightCount == 1 ? "" : "s"));
}

// A global palette needs every frame before the first can be written, so the GIF writer keeps them
// all (3 bytes per pixel). Refused up front when that would take more than half the machine's memory.
void checkGlobalPaletteMemory(int frames, int width, int height) {
  const double bytes = 3.0 * frames * width * height;
  const double memory =
      static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  if (memory > 0 && bytes > 0.5 * memory)
    throw InputError(
        SourceLocation{"--palette"},
        fmt::format("a global GIF palette keeps every frame until the end: {} frames of {}x{} need "
                    "{:.1f} GiB, more than half of this machine's {:.1f} GiB; use --palette per-frame "
                    "(frames are then written as they come), fewer frames or a smaller size",
                    frames, width, height, bytes / (1 << 30), memory / (1 << 30)));
}

int runAnimate(const AnimateCommandOptions& options) {
  PreparedScene prepared = prepareScene(options.input, options.overrides);
  const RenderSettings& settings = prepared.description.render;
  AnimationSettings animation = prepared.description.animation.value_or(AnimationSettings{});
  if (options.frames) animation.frames = *options.frames;
  if (options.fps) animation.fps = *options.fps;
  if (!options.orbit.empty())
    animation.orbitLight = parseOrbit(options.orbit, prepared.scene.appearance.lights.size());

  // render.output names `lancer render`'s still image: an animation never writes over it unasked.
  const std::string& output = options.output;
  if (output.empty())
    throw InputError(
        SourceLocation{options.input},
        "no output: give -o FILE.gif, -o FILE.png (animated PNG) or -o frame_%04d.png (numbered frames)");
  const std::optional<FramePattern> pattern = parseFramePattern(output);
  const ImageWriteOptions stillOptions = imageWriteOptions(settings);
  std::optional<GifWriter> gif;
  std::optional<ApngWriter> apng;
  StagedFrames frames;
  const ImageFormat format = imageFormatFromPath(pattern ? pattern->name(0) : output);
  const bool animatedGif = !pattern && format == ImageFormat::Gif;
  if (!animatedGif && !options.dither.empty())
    throw InputError(SourceLocation{"--dither"}, "--dither applies to an animated .gif only");
  if (!animatedGif && !options.palette.empty())
    throw InputError(SourceLocation{"--palette"}, "--palette applies to an animated .gif only");
  if (pattern && options.loop)
    throw InputError(SourceLocation{"--loop"},
                     "--loop applies to an animated .gif or .png, not to numbered frames");
  const int loop = options.loop.value_or(kGifLoopForever);
  if (pattern) {
    AtomicFileWriter probe(pattern->name(0));  // a bad folder fails now, not after the first frame
  } else if (format == ImageFormat::Gif) {
    GifOptions gifOptions;
    gifOptions.fps = animation.fps;
    gifOptions.loopCount = loop;
    gifOptions.curve = stillOptions.curve;
    gifOptions.palette = options.palette == "per-frame" ? GifPalette::PerFrame : GifPalette::Global;
    gifOptions.dither =
        options.dither == "none"
            ? Dither::None
            : (options.dither == "floyd-steinberg" ? Dither::FloydSteinberg : Dither::Ordered);
    if (gifOptions.palette == GifPalette::Global)
      checkGlobalPaletteMemory(animation.frames, settings.width, settings.height);
    gif.emplace(output, settings.width, settings.height, gifOptions);  // fails now on a bad folder
    if (!options.overrides.quiet && std::abs(gifActualFrameRate(animation.fps) - animation.fps) > 1e-9)
      std::fprintf(stderr,
                   "lancer: GIF delays are whole 1/100 s: %g fps plays at %.4g fps (a delay of %d/100 s)\n",
                   animation.fps, gifActualFrameRate(animation.fps), gifFrameDelay(animation.fps));
  } else if (format == ImageFormat::Png) {
    ApngOptions apngOptions;
    apngOptions.fps = animation.fps;
    // --loop counts repeats after the first showing (GIF's meaning); APNG counts plays.
    apngOptions.loopCount = loop == kGifLoopForever ? 0 : (loop == kGifPlayOnce ? 1 : loop + 1);
    apngOptions.curve = stillOptions.curve;
    apngOptions.alpha = settings.transparentBackground;
    apng.emplace(output, settings.width, settings.height, animation.frames, apngOptions);
  } else {
    throw InputError(
        SourceLocation{output},
        "an animation is written as .gif, as an animated .png, or as numbered frames with %04d in the "
        "name (frame_%04d.png, .bmp or .ppm)");
  }

  const RenderOptions renderOptions = commandRenderOptions(options.overrides);
  const bool progress = showProgress(options.overrides);
  auto onProgress = [&](const AnimationProgress& p) {
    const double done = (p.frame + p.frameProgress.fraction) / p.frames;
    const double eta = done > 0 ? p.seconds * (1 - done) / done : 0;
    std::fprintf(
        stderr, "\r  frame %d/%d  %5.1f%%  %7.2f Mrays/s  ETA %6.1f s ", p.frame + 1, p.frames, 100 * done,
        p.frameProgress.seconds > 0 ? p.frameProgress.rays / p.frameProgress.seconds * 1e-6 : 0.0, eta);
    std::fflush(stderr);
  };
  const AnimationStats stats = renderAnimation(
      prepared.scene, prepared.accelerator, prepared.description, animation, renderOptions,
      [&](int frame, const Image& image) {
        if (gif) {
          gif->addFrame(image);
        } else if (apng) {
          apng->addFrame(image);
        } else {
          frames.write(pattern->name(frame), image, stillOptions);
        }
      },
      progress ? std::function<void(const AnimationProgress&)>(onProgress) : nullptr);
  if (progress) std::fputc('\n', stderr);
  if (stats.cancelled)
    return interruptedExit(output);  // the writers' destructors remove their temporary files
  if (gif) gif->finish();
  if (apng) apng->finish();
  if (pattern) frames.publish();
  if (!options.overrides.quiet) {
    std::fprintf(stderr,
                 "%s: %d frames %dx%d, %zu faces, load %.3f s, build %.3f s (once), frames %.3f s "
                 "(%.3f s/frame, %.2f Mrays/s)\n",
                 output.c_str(), animation.frames, settings.width, settings.height,
                 prepared.scene.geometry.faces.size(), prepared.loadSeconds, prepared.buildSeconds,
                 stats.seconds, stats.seconds / animation.frames,
                 stats.seconds > 0 ? stats.rays / stats.seconds * 1e-6 : 0.0);
  }
  return kExitOk;
}

}  // namespace

void addAnimateCommand(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<AnimateCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "animate",
      "Render an orbit of the camera or of a light as an animated GIF, an animated PNG or numbered frames");
  command->add_option("input", options->input, "Scene file (.toml) or gmsh mesh (.msh)")->required();
  command->add_option("-o,--output", options->output,
                      "Output (required): NAME.gif (animated, looping), NAME.png (animated PNG) or "
                      "NAME_%04d.png/.bmp/.ppm (one "
                      "file per frame)");
  command->add_option("--frames", options->frames, "Number of frames")->check(CLI::Range(1, kMaxFrames));
  command->add_option("--fps", options->fps, "Frames per second")->check(CLI::Range(0.01, 100.0));
  command->add_option("--orbit", options->orbit, "What turns: camera or light:K");
  command
      ->add_option("--loop", options->loop,
                   "Repeats after the first showing: 0 forever (default), -1 play once")
      ->check(CLI::Range(-1, 65535));
  command
      ->add_option("--dither", options->dither, "GIF dithering: ordered (default), floyd-steinberg or none")
      ->check(CLI::IsMember({"none", "ordered", "floyd-steinberg"}));
  command->add_option("--palette", options->palette, "GIF palette: global (default, no flicker) or per-frame")
      ->check(CLI::IsMember({"global", "per-frame"}));
  addSceneOverrideOptions(*command, options->overrides);
  command->callback([options, &runner] { runner = [options] { return runAnimate(*options); }; });
}

}  // namespace lancer::cli
