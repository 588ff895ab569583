#include "lancer/image/exr_io.hpp"

#include <fmt/format.h>

#include "lancer/util/input_error.hpp"

#if LANCER_HAVE_OPENEXR
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <cstring>
#include <limits>

#include "lancer/image/atomic_file.hpp"
#endif

namespace lancer {

#if LANCER_HAVE_OPENEXR
namespace {

// OpenEXR's output stream over an AtomicFileWriter: EXR writes the line offset table last, after
// seeking back, so every write goes to the position the stream keeps.
class AtomicExrStream : public Imf::OStream {
 public:
  explicit AtomicExrStream(AtomicFileWriter& file) : Imf::OStream(file.targetPath().c_str()), file_(file) {}
  void write(const char c[], int n) override {
    if (!file_.writeAt(position_, c, static_cast<std::size_t>(n))) file_.throwIfFailed();
    position_ += static_cast<std::uint64_t>(n);
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t pos) override { position_ = pos; }

 private:
  AtomicFileWriter& file_;
  std::uint64_t position_ = 0;
};

constexpr std::size_t kRgbaStride = sizeof(Rgba);

Imf::Slice floatSlice(const void* base, std::size_t xStride, std::size_t yStride, double fill = 0.0) {
  return Imf::Slice(Imf::FLOAT, static_cast<char*>(const_cast<void*>(base)), xStride, yStride, 1, 1, fill);
}

}  // namespace

bool exrSupported() { return true; }

void writeExr(const std::string& path, const Image& image, const ExrLayers& layers) {
  if (image.empty()) throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) EXR");
  const int width = image.width(), height = image.height();
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  Imf::FrameBuffer frame;
  const auto* base = reinterpret_cast<const char*>(image.pixels().data());
  const std::size_t row = kRgbaStride * static_cast<std::size_t>(width);
  const char* names[4] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], floatSlice(base + c * sizeof(float), kRgbaStride, row));
  }
  const auto addVec3 = [&](const std::vector<Vec3>& layer, const char* const(&channels)[3]) {
    if (layer.empty()) return;
    if (layer.size() != pixels)
      throw std::invalid_argument("writeExr: a layer's size differs from the image's");
    const auto* data = reinterpret_cast<const char*>(layer.data());
    for (int c = 0; c < 3; ++c) {
      header.channels().insert(channels[c], Imf::Channel(Imf::FLOAT));
      frame.insert(channels[c], floatSlice(data + c * sizeof(float), sizeof(Vec3), sizeof(Vec3) * width));
    }
  };
  addVec3(layers.albedo, {"albedo.R", "albedo.G", "albedo.B"});
  addVec3(layers.normal, {"normal.X", "normal.Y", "normal.Z"});
  if (!layers.depth.empty()) {
    if (layers.depth.size() != pixels) throw std::invalid_argument("writeExr: the depth's size differs");
    header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
    frame.insert("Z", floatSlice(layers.depth.data(), sizeof(float), sizeof(float) * width));
  }
  AtomicFileWriter file(path);
  try {
    AtomicExrStream stream(file);
    Imf::OutputFile out(stream, header, 1);
    out.setFrameBuffer(frame);
    out.writePixels(height);
  } catch (const InputError&) {
    throw;  // a failed write, with its reason (the temporary file is gone)
  } catch (const std::exception& e) {
    file.discard();
    throw InputError(SourceLocation{path}, fmt::format("EXR encoding failed: {}", e.what()));
  }
  file.commit();
}

Image readExr(const std::string& path, ExrLayers* layers) {
  try {
    Imf::InputFile in(path.c_str(), 1);
    const Imath::Box2i window = in.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
      throw InputError(SourceLocation{path}, fmt::format("unsupported EXR size {}x{}", width, height));
    Image image(width, height);
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    // Slices are addressed from the data window's origin (OpenEXR's convention).
    const std::ptrdiff_t origin =
        static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width;
    Imf::FrameBuffer frame;
    char* base =
        reinterpret_cast<char*>(image.pixels().data()) - origin * static_cast<std::ptrdiff_t>(kRgbaStride);
    const char* names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
      frame.insert(names[c], floatSlice(base + c * sizeof(float), kRgbaStride, kRgbaStride * width,
                                        c == 3 ? 1.0 : 0.0));
    const Imf::ChannelList& channels = in.header().channels();
    const auto readVec3 = [&](std::vector<Vec3>& layer, const char* const(&names3)[3]) {
      if (channels.findChannel(names3[0]) == nullptr) return;
      layer.assign(pixels, Vec3{0, 0, 0});
      char* data = reinterpret_cast<char*>(layer.data()) - origin * static_cast<std::ptrdiff_t>(sizeof(Vec3));
      for (int c = 0; c < 3; ++c)
        frame.insert(names3[c], floatSlice(data + c * sizeof(float), sizeof(Vec3), sizeof(Vec3) * width));
    };
    if (layers != nullptr) {
      *layers = {};
      readVec3(layers->albedo, {"albedo.R", "albedo.G", "albedo.B"});
      readVec3(layers->normal, {"normal.X", "normal.Y", "normal.Z"});
      if (channels.findChannel("Z") != nullptr) {
        layers->depth.assign(pixels, 0.0f);
        frame.insert("Z", floatSlice(reinterpret_cast<char*>(layers->depth.data()) -
                                         origin * static_cast<std::ptrdiff_t>(sizeof(float)),
                                     sizeof(float), sizeof(float) * width));
      }
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(SourceLocation{path}, fmt::format("unreadable EXR: {}", e.what()));
  }
}

#else

namespace {
[[noreturn]] void unsupported(const std::string& path) {
  throw InputError(SourceLocation{path},
                   "this lancer was built without OpenEXR: install libopenexr-dev (scripts/setup.sh) and "
                   "rebuild, or write a .png");
}
}  // namespace

bool exrSupported() { return false; }
void writeExr(const std::string& path, const Image&, const ExrLayers&) { unsupported(path); }
Image readExr(const std::string& path, ExrLayers*) { unsupported(path); }

#endif

}  // namespace lancer
