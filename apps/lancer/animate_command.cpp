// `lancer animate SCENE.toml -o turntable.gif`: the camera or a light orbits the scene; one
// accelerator build serves every frame. Output: an animated GIF, an animated PNG, or numbered frames.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "commands.hpp"
#include "lancer/image/animation_writer.hpp"
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
  AnimationOutputOptions outputOptions;
  outputOptions.frames = animation.frames;
  outputOptions.fps = animation.fps;
  outputOptions.loop = options.loop;
  outputOptions.dither = options.dither;
  outputOptions.palette = options.palette;
  outputOptions.still = imageWriteOptions(settings);
  outputOptions.transparentBackground = settings.transparentBackground;
  AnimationWriter writer(output, settings.width, settings.height, outputOptions);
  if (!options.overrides.quiet && !writer.frameRateNote().empty())
    std::fprintf(stderr, "%s\n", writer.frameRateNote().c_str());

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
      [&](int frame, const Image& image) { writer.addFrame(frame, image); },
      progress ? std::function<void(const AnimationProgress&)>(onProgress) : nullptr);
  if (progress) std::fputc('\n', stderr);
  if (stats.cancelled)
    return interruptedExit(output);  // the writers' destructors remove their temporary files
  writer.finish();
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
