// `lancer animate SCENE.toml -o turntable.gif`: the camera or a light orbits the scene; one
// accelerator build serves every frame. Output: an animated GIF or PNG, an MP4 or WebM video, or
// numbered frames.
// The frames are work items: one process renders them all, the ranks of an MPI job share them, or a
// job-array task renders its share (--shard) as numbered frames for `lancer assemble`.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "command_distribution.hpp"
#include "commands.hpp"
#include "lancer/cluster/shard.hpp"
#include "lancer/image/animation_writer.hpp"
#include "lancer/image/frame_sequence.hpp"
#include "lancer/image/legend.hpp"
#include "lancer/render/animation.hpp"
#include "lancer/render/step_animation.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "lancer/scene/setting_checks.hpp"
#include "lancer/util/check.hpp"
#include "lancer/util/stopwatch.hpp"
#include "piped_output.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {
namespace {

struct AnimateCommandOptions {
  std::string input;                // the scene or mesh (takeMeshInput)
  std::vector<std::string> inputs;  // as given: the input, then views
  std::string output;
  std::optional<int> frames;
  std::optional<double> fps;
  std::string orbit;
  std::string over;                  // --over orbit|steps
  std::optional<std::string> label;  // --label "t = {time:.3g} s"
  AnimationOutputOptions writer;     // --loop, --dither, --palette (the rest from the scene)
  std::string shard;                 // --shard I/N or auto
  std::string frameRange;            // --frame-range A-B
  bool skipExisting = false;
  SceneOverrides overrides;
};

// The frames this process renders: all of them, or a job-array task's share (--shard, --frame-range),
// less those already on disk (--skip-existing).
std::vector<int> framesToRender(const AnimateCommandOptions& options, const AnimationWriter& out,
                                const AnimationOutputOptions& format, int width, int height, bool quiet) {
  const bool sharded = !options.shard.empty() || !options.frameRange.empty();
  if ((sharded || options.skipExisting) && !out.pattern())
    throw InputError(SourceLocation{!options.shard.empty()        ? "--shard"
                                    : !options.frameRange.empty() ? "--frame-range"
                                                                  : "--skip-existing"},
                     "--shard, --frame-range and --skip-existing write numbered frames: give -o "
                     "frames/%04d.png, then `lancer assemble 'frames/%04d.png' -o OUT.gif`");
  std::optional<FrameRange> range;
  if (!options.frameRange.empty()) range = parseFrameRange(options.frameRange, format.frames);
  ScheduledShard shard;
  if (!options.shard.empty()) shard = resolveShard(options.shard, processEnvironment());
  std::vector<int> frames = shardFrames(format.frames, range, shard.shard);
  if (!options.shard.empty() && !quiet)
    std::fprintf(stderr, "lancer: task %d of %d (%s) renders frames %s\n", shard.shard.index,
                 shard.shard.count, shard.source.c_str(), describeFrames(frames).c_str());
  else if (sharded && !quiet)
    std::fprintf(stderr, "lancer: --frame-range %s renders frames %s\n", options.frameRange.c_str(),
                 describeFrames(frames).c_str());
  if (options.skipExisting) {
    const std::size_t before = frames.size();
    std::erase_if(frames, [&](int k) { return completeFrameExists(out.pattern()->name(k), width, height); });
    if (!quiet && before != frames.size())
      std::fprintf(stderr, "lancer: --skip-existing: %zu of %zu frames are already there\n",
                   before - frames.size(), before);
  }
  return frames;
}

int runAnimate(const AnimateCommandOptions& options) {
  if (options.output == "-")
    throw InputError(SourceLocation{"-o"},
                     "animate writes a file (.gif, .png or numbered frames), not stdout: give -o NAME.gif "
                     "(`lancer render -o -` sends one PNG to stdout)");
  // A job-array task works alone; a --frame-range under mpirun is shared by the ranks.
  const std::unique_ptr<WorkDistribution> distribution = commandDistribution(!options.shard.empty());
  // Over steps, the meshes as read (every step) stay for the frames' scenes.
  const bool overStepsAsked = options.over == "steps";
  const bool sceneOverSteps = options.over.empty() && sceneAnimatesOverSteps(options.input);
  PreparedRender prepared =
      prepareScene(options.input, options.overrides, {}, overStepsAsked || sceneOverSteps);
  const RenderSettings& settings = prepared.description.render;
  AnimationSettings animation = prepared.description.animation.value_or(AnimationSettings{});
  if (!options.over.empty()) animation.overSteps = overStepsAsked;
  if (options.frames) {
    animation.frames = checkFrames(*options.frames, SettingName{SourceLocation{"--frames"}, "--frames"});
    animation.framesGiven = true;
  }
  if (options.fps) animation.fps = checkFps(*options.fps, SettingName{SourceLocation{"--fps"}, "--fps"});
  if (options.label) {
    formatStepLabel(*options.label, 0.0, 0, SourceLocation{"--label"});  // unknown names: said now
    animation.label = *options.label;
  }
  if (!animation.label.empty() && !animation.overSteps)
    throw InputError(SourceLocation{options.label ? "--label" : options.input},
                     "a label shows the time and step of an animation over steps: add --over steps (or "
                     "over = \"steps\" in [animation])");
  if (!options.orbit.empty())
    animation.orbitLight = parseOrbit(options.orbit, prepared.scene.appearance.lights.size());
  std::optional<StepScenes> steps;
  // The meshes were kept (and no accelerator built) exactly when the frames go over steps: both read
  // --over and the scene's [animation] over.
  LANCER_DCHECK(prepared.meshes.empty(), ==, !animation.overSteps);
  if (animation.overSteps) {
    steps.emplace(prepared.description, prepared.meshes, animation, parseAccelKind(options.overrides.accel),
                  options.overrides.threads);
    animation = steps->animation();
    // The frames' scenes are the steps' own: prepareScene's scene goes (its legends stay).
    releaseSceneForSteps(prepared);
  }

  // render.output names `lancer render`'s still image: an animation never writes over it unasked, and
  // without -o goes to the input's name as a .gif in the current folder.
  const std::string output =
      options.output.empty() ? outputNamedAfter(options.input, ".gif") : options.output;
  checkTransparentOutput(options.overrides, output);
  const bool talks = distribution->delivers();  // rank 0 of an MPI job, or a single process
  AnimationOutputOptions format = options.writer;
  if (format.loop) checkLoop(*format.loop, SettingName{SourceLocation{"--loop"}, "--loop"});
  format.frames = animation.frames;
  format.fps = animation.fps;
  format.still = imageWriteOptions(settings);
  format.transparentBackground = settings.transparentBackground;
  const bool quiet = options.overrides.quiet || !talks;
  // Every rank checks the options the same way, so that all fail alike; only rank 0 keeps a writer.
  std::optional<AnimationWriter> out;
  out.emplace(output, settings.width, settings.height, format, /*checkOnly=*/!talks);
  if (!quiet && !out->frameRateNote().empty()) std::fprintf(stderr, "%s\n", out->frameRateNote().c_str());
  if (!quiet && steps && !steps->frames().note.empty())
    std::fprintf(stderr, "%s\n", steps->frames().note.c_str());
  const std::vector<int> frames =
      framesToRender(options, *out, format, settings.width, settings.height, quiet);

  RenderOptions renderOptions = commandRenderOptions(options.overrides);
  renderOptions.threads = commandThreads(options.overrides.threads, *distribution);
  const bool progress = talks && showProgress(options.overrides);
  const bool alone = distribution->ranks() == 1;
  const Stopwatch stopwatch;
  std::uint64_t rays = 0;
  int current = 0;  // the item (index into `frames`) being rendered here
  RenderOptions frameOptions = renderOptions;
  if (progress && alone) {
    frameOptions.onProgress = [&](const RenderProgress& p) {
      const double done = (current + p.fraction) / static_cast<double>(frames.size());
      const double seconds = stopwatch.seconds();
      const double eta = done > 0 ? seconds * (1 - done) / done : 0;
      std::fprintf(stderr, "\r  frame %d/%zu  %5.1f%%  %7.2f Mrays/s  ETA %6.1f s ", current + 1,
                   frames.size(), 100 * done, p.seconds > 0 ? p.rays / p.seconds * 1e-6 : 0.0, eta);
      std::fflush(stderr);
    };
  }
  DistributedWork work;
  work.itemCount = static_cast<int>(frames.size());
  work.window = 2 * distribution->ranks() + 2;
  work.cancel = renderOptions.cancel;
  work.render = [&](int item) {
    current = item;
    RenderStats stats;
    const int frame = frames[static_cast<std::size_t>(item)];
    Image image = steps ? steps->render(frame, frameOptions, &stats)
                        : renderAnimationFrame(prepared.scene, prepared.accelerator, prepared.description,
                                               animation, frame, frameOptions, &stats);
    if (const auto& fields = prepared.scene.fieldColors; fields && !steps)  // steps draw their own
      drawLegends(image, fields->legends, fields->legendPlacement, prepared.description.render.srgb);
    rays += stats.rays;
    return image;
  };
  work.deliver = [&](int item, const Image& image) {
    out->addFrame(frames[static_cast<std::size_t>(item)],
                  out->takesRadiance() ? image : displayImage(image, settings));
  };
  if (progress && !alone) {
    work.onDelivered = [&](int done, int total) {
      const double seconds = stopwatch.seconds();
      std::fprintf(stderr, "\r  frame %d/%d on %d ranks  ETA %6.1f s ", done, total, distribution->ranks(),
                   seconds * (total - done) / std::max(done, 1));
      std::fflush(stderr);
    };
  }
  bool finished = false;
  try {
    finished = distribution->run(work);
  } catch (const NonFiniteRenderError& e) {
    if (progress) std::fputc('\n', stderr);
    throw InputError(SourceLocation{options.input},
                     fmt::format("frame {}: {}", frames[static_cast<std::size_t>(current)], e.what()));
  } catch (...) {
    if (progress) std::fputc('\n', stderr);  // the error goes below the progress line
    throw;
  }
  if (progress) std::fputc('\n', stderr);
  // The writers' destructors remove their temporary files; rank 0 alone says so.
  if (!finished) return talks ? interruptedExit(output) : kExitInterrupted;
  if (!talks) return kExitOk;
  out->finish();
  const double seconds = stopwatch.seconds();
  if (!options.overrides.quiet) {
    const std::string speed = alone
                                  ? fmt::format(", {:.2f} Mrays/s", seconds > 0 ? rays / seconds * 1e-6 : 0.0)
                                  : fmt::format(" on {} ranks", distribution->ranks());
    std::fprintf(stderr,
                 "%s: %zu frames %dx%d, %zu faces, load %.3f s, build %.3f s (once), frames %.3f s "
                 "(%.3f s/frame%s)\n",
                 output.c_str(), frames.size(), settings.width, settings.height,
                 steps ? steps->faceCount() : prepared.scene.geometry.faces.size(), prepared.loadSeconds,
                 steps ? steps->firstBuildSeconds() : prepared.buildSeconds, seconds,
                 frames.empty() ? 0.0 : seconds / static_cast<double>(frames.size()), speed.c_str());
  }
  if (steps && !options.overrides.quiet && steps->rebuilds() > 0)
    std::fprintf(stderr,
                 "over steps: %d frames rebuilt their scene in %.3f s (%.3f s/frame, %.0f%% of those frames' "
                 "time, rebuild and render; %d updated in place), of which the accelerator %.3f s (%d "
                 "refitted, %d built)\n",
                 steps->rebuilds(), steps->rebuildSeconds(), steps->rebuildSeconds() / steps->rebuilds(),
                 100 * steps->rebuildShare(), steps->updatesInPlace(), steps->accelSeconds(), steps->refits(),
                 steps->rebuilds() - steps->refits());
  if (options.overrides.timings && talks) {
    std::fprintf(stderr, "%s\n", formatStageTimes(prepared.stages).c_str());
    if (steps && steps->rebuilds() > 0)
      std::fprintf(stderr, "rebuilds' %s\n", formatStageTimes(steps->rebuildStages()).c_str());
  }
  return kExitOk;
}

}  // namespace

void addAnimateCommand(CLI::App& app, CommandRunner& runner) {
  auto options = std::make_shared<AnimateCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "animate",
      "Render an orbit of the camera or of a light as an animated GIF, an animated PNG or numbered frames");
  addInputOption(*command, options->inputs);
  addSceneViewOptions(*command, options->overrides);
  command
      ->add_option(
          "-o,--output", options->output,
          "Output: NAME.gif (animated, looping), NAME.png (animated PNG), NAME.mp4 (H.264), NAME.webm "
          "(VP9) or NAME_%04d.png/.jpg/.webp/.bmp/.ppm (one file per frame); default: the input's name "
          "as a .gif in the current folder")
      ->group(kOutputGroup);
  command->add_option("--frames", options->frames, fmt::format("Number of frames (1 to {})", kMaxFrames))
      ->group(kOutputGroup);
  command
      ->add_option("--fps", options->fps, fmt::format("Frames per second ({:g} to {:g})", kMinFps, kMaxFps))
      ->group(kOutputGroup);
  command->add_option("--orbit", options->orbit, "What turns: camera or light:K")->group(kCameraGroup);
  command
      ->add_option("--over", options->over,
                   "What the frames run through: orbit (default) or steps (the results' time steps)")
      ->check(CLI::IsMember({"orbit", "steps"}))
      ->group(kResultsGroup);
  command
      ->add_option(
          "--label", options->label,
          "Over steps: text drawn into each frame, {time} and {step} replaced (\"t = {time:.3g} s\")")
      ->group(kResultsGroup);
  addAnimationWriterOptions(*command, options->writer);
  addSceneOutputOptions(*command, options->overrides);
  command
      ->add_option("--shard", options->shard,
                   "Job arrays: render only frames k with k % N == I (I/N), or take I and N from SLURM or "
                   "mpirun (auto); writes numbered frames")
      ->group(kClusterGroup);
  command->add_option("--frame-range", options->frameRange, "Render only frames A to B (A-B, both included)")
      ->group(kClusterGroup);
  command
      ->add_flag("--skip-existing", options->skipExisting,
                 "Keep numbered frames that are already complete images (resume a pre-empted job)")
      ->group(kClusterGroup);
  command->callback([options, &runner] {
    takeInputFromGmshView(options->inputs, options->overrides);
    runner = [options] {
      options->input = takeMeshInput(options->inputs, options->overrides.views);
      return runAnimate(*options);
    };
  });
}

}  // namespace lancer::cli
