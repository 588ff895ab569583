// lancer.animate: `lancer animate` from Python. One scene build and accelerator serve every frame;
// the frames go to the library's AnimationWriter, as the CLI's do, so the files are the same.
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cstdio>

#include "bindings.hpp"
#include "lancer/image/animation_writer.hpp"
#include "lancer/render/animation.hpp"
#include "lancer/render/step_animation.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "lancer/scene/setting_checks.hpp"
#include "render_session.hpp"

namespace lancer::python {
namespace {

void animate(const py::object& target, const std::string& output, const RenderArguments& arguments,
             const std::optional<int>& frames, const std::optional<double>& fps,
             const std::optional<std::string>& orbit, const std::optional<int>& loop,
             const std::optional<std::string>& dither, const std::optional<std::string>& palette,
             const std::optional<std::string>& over, const std::optional<std::string>& label,
             const std::string& command) {
  if (over && *over != "orbit" && *over != "steps")
    throw py::value_error(fmt::format("over='{}': use 'orbit' or 'steps'", *over));
  if (frames) checkFrames(*frames, SettingName{SourceLocation{"frames"}, "frames"});
  if (fps) checkFps(*fps, SettingName{SourceLocation{"fps"}, "fps"});
  if (loop) checkLoop(*loop, SettingName{SourceLocation{"loop"}, "loop"});
  if (dither && *dither != "ordered" && *dither != "floyd-steinberg" && *dither != "none")
    throw py::value_error(fmt::format("dither='{}': use 'ordered', 'floyd-steinberg' or 'none'", *dither));
  if (palette && *palette != "global" && *palette != "per-frame")
    throw py::value_error(fmt::format("palette='{}': use 'global' or 'per-frame'", *palette));
  const PythonScene source = sceneOf(target);
  // Over steps, the meshes as read (every step) build each frame's scene (render/step_animation.hpp).
  const bool overSteps =
      over ? *over == "steps" : source.description.animation && source.description.animation->overSteps;
  PreparedRender prepared =
      prepareRender(source, renderOverridesFromArguments(arguments), arguments.threads, overSteps);
  const RenderSettings& settings = prepared.description.render;
  AnimationSettings animation = prepared.description.animation.value_or(AnimationSettings{});
  if (frames) animation.frames = *frames, animation.framesGiven = true;
  if (fps) animation.fps = *fps;
  if (orbit) animation.orbitLight = parseOrbit(*orbit, sceneLightCount(prepared.scene));
  animation.overSteps = overSteps;
  if (label) {
    formatStepLabel(*label, 0.0, 0, SourceLocation{"label"});  // unknown names: said now
    if (!overSteps)
      throw InputError(SourceLocation{"label"},
                       "a label shows the time and step of an animation over steps: add over=\"steps\"");
    animation.label = *label;
  }
  std::optional<StepScenes> steps;
  if (animation.overSteps) {
    py::gil_scoped_release release;
    steps.emplace(prepared.description, prepared.meshes, animation, kDefaultAccel, arguments.threads);
    animation = steps->animation();
    releaseSceneForSteps(prepared);  // one scene and one accelerator at a time: the frame's
  }

  AnimationOutputOptions outputOptions;
  outputOptions.frames = animation.frames;
  outputOptions.fps = animation.fps;
  outputOptions.loop = loop;
  outputOptions.dither = dither.value_or("");
  outputOptions.palette = palette.value_or("");
  outputOptions.still.curve = settings.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  outputOptions.still.alpha = settings.transparentBackground ? AlphaChannel::Always : AlphaChannel::Never;
  outputOptions.transparentBackground = settings.transparentBackground;
  outputOptions.still.metadata.software = softwareName();
  outputOptions.still.metadata.command = command;
  AnimationWriter writer(output, settings.width, settings.height, outputOptions);
  if (!writer.frameRateNote().empty())
    if (PyErr_WarnEx(PyExc_UserWarning, writer.frameRateNote().c_str(), 1) != 0)
      throw py::error_already_set();

  InterruptibleRender render(arguments.threads, arguments.progress);
  AnimationStats stats;
  {
    py::gil_scoped_release release;
    const auto deliver = [&](int frame, const Image& rendered) {
      Image image = rendered;
      if (!steps) drawSceneLegends(image, prepared);  // a step's frame has its own scene's legends
      writer.addFrame(frame, writer.takesRadiance() ? image : displayImage(image, settings));
    };
    if (steps) {
      for (int frame = 0; frame < steps->frameCount() && !stats.cancelled; ++frame) {
        RenderStats frameStats;
        const Image image = steps->render(frame, render.options, &frameStats);
        stats.cancelled = frameStats.cancelled || (render.options.cancel && render.options.cancel->load());
        if (!stats.cancelled) deliver(frame, image);
      }
    } else {
      stats = renderAnimation(prepared.scene, prepared.accelerator, prepared.description, animation,
                              render.options, deliver);
    }
  }
  render.finish();  // KeyboardInterrupt: the writer's destructor removes its temporary files
  if (!stats.cancelled) writer.finish();
}

}  // namespace

void bindAnimate(py::module_& module) {
  module.def("_animate", &animate, py::arg("target"), py::arg("output"), py::arg("arguments"),
             py::arg("frames"), py::arg("fps"), py::arg("orbit"), py::arg("loop"), py::arg("dither"),
             py::arg("palette"), py::arg("over"), py::arg("label"), py::arg("command") = "");
}

}  // namespace lancer::python
