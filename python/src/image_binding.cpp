// Writing a lancer.Image (the numpy array render returned) to .png, .jpg, .webp, .bmp, .ppm, .gif or .exr
// with the library's writers: the pixels the lancer command writes for the same render.
#include <pybind11/numpy.h>

#include <pybind11/stl.h>

#include <fmt/format.h>

#include "bindings.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer::python {
namespace {

void writeArray(const std::string& path, const py::array& array, bool srgb, const std::optional<int>& quality,
                bool lossless, const std::optional<double>& dpi, const std::string& command) {
  ImageWriteOptions options;
  options.curve = srgb ? TransferCurve::Srgb : TransferCurve::Linear;
  if (quality) requireImageQuality(*quality, SourceLocation{"quality"});
  if (dpi) requireDpi(*dpi, SourceLocation{"dpi"});
  options.quality = quality.value_or(kDefaultImageQuality);
  options.lossless = lossless;
  options.metadata.dpi = dpi.value_or(0);
  options.metadata.software = softwareName();
  options.metadata.command = command;
  if (array.ndim() != 3 || (array.shape(2) != 3 && array.shape(2) != 4) || array.shape(0) < 1 ||
      array.shape(1) < 1)
    throw py::value_error(
        fmt::format("an image is an (H, W, 3) or (H, W, 4) array; got {} dimensions", array.ndim()));
  if (array.shape(0) > kMaxImageSide || array.shape(1) > kMaxImageSide)
    throw py::value_error(fmt::format("an image side is at most {} pixels", kMaxImageSide));
  const int height = static_cast<int>(array.shape(0)), width = static_cast<int>(array.shape(1));
  const int channels = static_cast<int>(array.shape(2));
  if (array.dtype().is(py::dtype::of<std::uint8_t>())) {
    const auto samples = py::array_t<std::uint8_t, py::array::c_style>::ensure(array);
    const py::gil_scoped_release release;
    writeImage8(path, width, height, channels, samples.data(), options);
    return;
  }
  if (array.dtype().kind() != 'f')
    throw py::value_error(fmt::format("an image holds uint8 or floating-point samples, not {}",
                                      py::str(array.dtype()).cast<std::string>()));
  // Linear floating point (dtype="float32"): encoded with the curve as the renderer's image would be.
  const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  Image image(width, height);
  const float* v = values.data();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x, v += channels)
      image.at(x, y) = Rgba{v[0], v[1], v[2], channels == 4 ? v[3] : 1.0f};
  options.alpha = channels == 4 ? AlphaChannel::Auto : AlphaChannel::Never;
  const py::gil_scoped_release release;
  writeImage(path, image, options);
}

}  // namespace

// Any PNG as (H, W, 4) uint8 RGBA, rows top to bottom (libpng through the library's reader).
py::array_t<std::uint8_t> readPngArray(const std::string& path) {
  Image image;
  {
    const py::gil_scoped_release release;
    image = readPng(path);
  }
  py::array_t<std::uint8_t> array(
      {static_cast<py::ssize_t>(image.height()), static_cast<py::ssize_t>(image.width()), py::ssize_t{4}});
  std::uint8_t* out = array.mutable_data();
  for (int y = 0; y < image.height(); ++y)
    encodeRow8(image.row(y), TransferCurve::Linear, 4, out + static_cast<std::size_t>(y) * image.width() * 4);
  return array;
}

void bindImage(py::module_& module) {
  module.def("_write_image", &writeArray, py::arg("path"), py::arg("array"), py::arg("srgb"),
             py::arg("quality") = py::none(), py::arg("lossless") = false, py::arg("dpi") = py::none(),
             py::arg("command") = "");
  module.def("read_png", &readPngArray, py::arg("path"), "A PNG file as an (H, W, 4) uint8 RGBA array");
}

}  // namespace lancer::python
