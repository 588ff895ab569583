// lancer.render: the scene (or a mesh's quick look) with the keyword arguments over its own settings,
// as the CLI's options are, traced with the GIL released; Ctrl-C stops it within a tile's time.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "bindings.hpp"
#include "lancer/image/pixel_encoding.hpp"
#include "lancer/render/progress_line.hpp"
#include "lancer/scene/render_limits.hpp"
#include "lancer/scene/setting_checks.hpp"
#include "render_session.hpp"

namespace lancer::python {
namespace {

// The keyword argument as the library's checks name it (setting_checks.hpp): "width".
SettingName argumentName(const char* name) { return {SourceLocation{name}, name}; }

template <typename Enum, std::size_t N>
std::optional<Enum> choiceArgument(const std::optional<std::string>& value, const char* name,
                                   const std::array<std::string_view, N>& names) {
  if (!value) return std::nullopt;
  if (const auto found = enumFromName<Enum>(names, *value)) return found;
  std::string choices;
  for (const std::string_view choice : names)
    choices += (choices.empty() ? "'" : ", '") + std::string(choice) + "'";
  throw py::value_error(fmt::format("{}='{}': use one of {}", name, *value, choices));
}

// 8-bit (H, W, 3 or 4) encoded with the settings' curve, or linear float32 (H, W, 4).
py::array toArray(const Image& image, const RenderSettings& settings, bool linearFloat) {
  const auto height = static_cast<py::ssize_t>(image.height()),
             width = static_cast<py::ssize_t>(image.width());
  if (linearFloat) {
    static_assert(sizeof(Rgba) == 4 * sizeof(float));
    py::array_t<float> array({height, width, py::ssize_t{4}});
    std::memcpy(array.mutable_data(), image.pixels().data(), image.pixels().size_bytes());
    return array;
  }
  const int channels = settings.transparentBackground ? 4 : 3;
  py::array_t<std::uint8_t> array({height, width, static_cast<py::ssize_t>(channels)});
  const TransferCurve curve = settings.srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  std::uint8_t* out = array.mutable_data();
  const Image shown = displayImage(image, settings);  // exposure and tone curve, as in the files
  for (int y = 0; y < shown.height(); ++y)
    encodeRow8(shown.row(y), curve, channels, out + static_cast<std::size_t>(y) * shown.width() * channels);
  return array;
}

}  // namespace

void requireThreads(int threads) { checkThreads(threads, argumentName("threads")); }

RenderOverrides renderOverridesFromArguments(const RenderArguments& arguments) {
  if (arguments.width) checkWidth(*arguments.width, argumentName("width"));
  if (arguments.height) checkHeight(*arguments.height, argumentName("height"));
  if (arguments.samples) checkSamples(*arguments.samples, argumentName("samples"));
  if (arguments.maxDepth) checkMaxDepth(*arguments.maxDepth, argumentName("max_depth"));
  requireThreads(arguments.threads);
  RenderOverrides overrides;
  overrides.width = arguments.width;
  overrides.height = arguments.height;
  overrides.samples = arguments.samples;
  overrides.maxDepth = arguments.maxDepth;
  overrides.shading = choiceArgument<ShadingMode>(arguments.shading, "shading", kShadingNames);
  overrides.sampler = choiceArgument<SamplerKind>(arguments.sampler, "sampler", kSamplerNames);
  overrides.srgb = arguments.srgb;
  if (arguments.encoding) {
    if (*arguments.encoding != "srgb" && *arguments.encoding != "linear")
      throw py::value_error(fmt::format("encoding='{}': use 'srgb' or 'linear'", *arguments.encoding));
    if (arguments.srgb && *arguments.srgb != (*arguments.encoding == "srgb"))
      throw py::value_error("srgb and encoding disagree: give encoding alone");
    overrides.srgb = *arguments.encoding == "srgb";
  }
  overrides.toneMap = choiceArgument<ToneMap>(arguments.toneMap, "tonemap", kToneMapNames);
  if (arguments.exposure) overrides.exposure = checkExposure(*arguments.exposure, argumentName("exposure"));
  overrides.denoise = arguments.denoise;
  overrides.transparentBackground = arguments.transparentBackground;
  overrides.edges = arguments.edges.value_or(false);
  overrides.samplesName = "samples";
  overrides.integrator = choiceArgument<IntegratorKind>(arguments.integrator, "integrator", kIntegratorNames);
  overrides.look = choiceArgument<Look>(arguments.look, "look", kLookNames);
  if (arguments.noise) overrides.noise = checkNoise(*arguments.noise, argumentName("noise"));
  if (arguments.adaptiveNoise)
    overrides.adaptiveNoise = checkAdaptiveNoise(*arguments.adaptiveNoise, argumentName("adaptive_noise"));
  applyResultArguments(arguments, overrides);
  return overrides;
}

PythonScene sceneOf(const py::object& target) {
  if (py::isinstance<Mesh>(target)) return quickLookOf(target.cast<std::shared_ptr<Mesh>>());
  if (py::isinstance<PythonScene>(target)) return target.cast<PythonScene>();
  throw py::type_error(fmt::format("render takes a lancer.Scene or a lancer.Mesh, not {}",
                                   py::repr(py::type::of(target)).cast<std::string>()));
}

InterruptibleRender::InterruptibleRender(int threads, bool progress) {
  options.threads = threads;
  options.cancel = &cancel_;
  options.progressInterval = 0.05;  // how often Python's signal handlers get a chance to run
  options.onProgress = [this, progress](const RenderProgress& p) {
    if (progress) printProgressLine(p);
    if (cancel_.load()) return;
    const py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) {
      cancel_.store(true);
      // Kept until the render returns on this thread: the error indicator is the thread's own.
      pending_ = std::make_unique<py::error_already_set>();
    }
  };
  progress_ = progress;
}

void InterruptibleRender::finish() {
  if (progress_) std::fputc('\n', stderr);
  if (pending_) {
    const std::unique_ptr<py::error_already_set> pending = std::move(pending_);
    throw py::error_already_set(*pending);
  }
}

PreparedRender prepareRender(PythonScene scene, const RenderOverrides& overrides, int threads,
                             bool keepMeshes) {
  std::vector<const Mesh*> given = {scene.quickLookMesh.get()};
  for (const std::shared_ptr<const Mesh>& mesh : scene.givenMeshes) given.push_back(mesh.get());
  PreparedRender prepared = [&] {
    const py::gil_scoped_release release;
    RenderRequest request;
    // Before the move below: both read the description.
    request.quickLookVolume = quickLookVolumeFor(scene, overrides, threads);
    request.givenVolumes = givenVolumesFor(scene, overrides, threads);
    request.description = std::move(scene.description);
    if (scene.quickLookMesh) request.quickLookMesh = *scene.quickLookMesh;
    request.givenMeshes = scene.givenMeshes;
    request.overrides = overrides;
    request.threads = threads;
    request.keepMeshes = keepMeshes;
    return lancer::prepareRender(std::move(request));
  }();
  // A mesh in memory warned when it was made (read_msh, Mesh): its warnings are not said again.
  for (const std::string& warning : sceneWarnings(prepared.scene))
    if (std::none_of(given.begin(), given.end(), [&](const Mesh* mesh) {
          return mesh && std::find(mesh->source.warnings.begin(), mesh->source.warnings.end(), warning) !=
                             mesh->source.warnings.end();
        }))
      warnUser(warning, 2);
  return prepared;
}

void bindRender(py::module_& module) {
  module.def(
      "_render",
      [](const py::object& target, const RenderArguments& arguments, bool linearFloat) {
        const RenderOverrides overrides = renderOverridesFromArguments(arguments);
        PreparedRender prepared = prepareRender(sceneOf(target), overrides, arguments.threads);
        const RenderSettings& settings = prepared.description.render;
        const Renderer renderer = prepared.renderer();
        InterruptibleRender render(arguments.threads, arguments.progress);
        RenderStats stats;
        Image image;
        try {
          py::gil_scoped_release release;
          image = renderer.renderFinal(render.options, &stats);
        } catch (const NonFiniteRenderError& e) {
          throw InputError(SourceLocation{prepared.description.path}, e.what());
        }
        render.finish();
        drawSceneLegends(image, prepared);
        py::dict info;
        info["srgb"] = settings.srgb;
        info["seconds"] = stats.seconds;
        info["rays"] = stats.rays;
        info["samples_per_pixel"] = stats.samplesPerPixel;
        return py::make_tuple(toArray(image, settings, linearFloat), info);
      },
      py::arg("target"), py::arg("arguments"), py::arg("linear_float"));

  py::class_<RenderArguments>(module, "_RenderArguments")
      .def(py::init<>())
      .def_readwrite("width", &RenderArguments::width)
      .def_readwrite("height", &RenderArguments::height)
      .def_readwrite("samples", &RenderArguments::samples)
      .def_readwrite("max_depth", &RenderArguments::maxDepth)
      .def_readwrite("shading", &RenderArguments::shading)
      .def_readwrite("sampler", &RenderArguments::sampler)
      .def_readwrite("integrator", &RenderArguments::integrator)
      .def_readwrite("look", &RenderArguments::look)
      .def_readwrite("noise", &RenderArguments::noise)
      .def_readwrite("adaptive_noise", &RenderArguments::adaptiveNoise)
      .def_readwrite("srgb", &RenderArguments::srgb)
      .def_readwrite("encoding", &RenderArguments::encoding)
      .def_readwrite("tonemap", &RenderArguments::toneMap)
      .def_readwrite("exposure", &RenderArguments::exposure)
      .def_readwrite("denoise", &RenderArguments::denoise)
      .def_readwrite("transparent_background", &RenderArguments::transparentBackground)
      .def_readwrite("edges", &RenderArguments::edges)
      .def_readwrite("threads", &RenderArguments::threads)
      .def_readwrite("progress", &RenderArguments::progress)
      .def_readwrite("color_map", &RenderArguments::colorMap)
      .def_readwrite("range", &RenderArguments::range)
      .def_readwrite("log", &RenderArguments::log)
      .def_readwrite("scale", &RenderArguments::scale)
      .def_readwrite("legend", &RenderArguments::legend)
      .def_readwrite("isolines", &RenderArguments::isolines)
      .def_readwrite("bands", &RenderArguments::bands)
      .def_readwrite("arrows", &RenderArguments::arrows)
      .def_readwrite("clip", &RenderArguments::clip)
      .def_readwrite("slices", &RenderArguments::slices)
      .def_readwrite("skin", &RenderArguments::skin)
      .def_readwrite("isosurfaces", &RenderArguments::isosurfaces)
      .def_readwrite("streamlines", &RenderArguments::streamlines);
}

}  // namespace lancer::python
