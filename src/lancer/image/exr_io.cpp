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
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <system_error>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/exr_chunk_table.hpp"
#include "lancer/util/memory_budget.hpp"
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

void writeExr(const std::string& path, const Image& image, const ExrLayers& layers,
              const ImageMetadata& metadata) {
  if (image.empty()) throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) EXR");
  const int width = image.width(), height = image.height();
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  // The standard attributes "comments" and "xDensity" (pixels per inch), and a string "software"
  // (OpenEXR has no standard one; readers show every string attribute).
  if (!metadata.command.empty()) Imf::addComments(header, metadata.command);
  if (!metadata.software.empty()) header.insert("software", Imf::StringAttribute(metadata.software));
  if (metadata.dpi > 0) Imf::addXDensity(header, static_cast<float>(metadata.dpi));
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

namespace {

// Scan lines per chunk of each compression (OpenEXR file layout, "Scan Line Based Compression").
std::uint64_t linesPerChunk(Imf::Compression compression) {
  switch (compression) {
    case Imf::ZIP_COMPRESSION:
    case Imf::PXR24_COMPRESSION:
      return 16;
    case Imf::PIZ_COMPRESSION:
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
    case Imf::DWAA_COMPRESSION:
      return 32;
    case Imf::DWAB_COMPRESSION:
      return 256;
    default:
      return 1;
  }
}

// Decoded bytes per stored byte at most: deflate's 1032:1 (ZIP, and PXR24 after its 4-to-3-byte
// floats), RLE's 128 bytes from 2; 0 where no simple bound holds (PIZ, B44, DWA).
std::uint64_t largestRatio(Imf::Compression compression) {
  switch (compression) {
    case Imf::NO_COMPRESSION:
      return 1;
    case Imf::RLE_COMPRESSION:
      return 64;
    case Imf::ZIPS_COMPRESSION:
    case Imf::ZIP_COMPRESSION:
      return 1032;
    case Imf::PXR24_COMPRESSION:
      return 1376;
    default:
      return 0;
  }
}

// Bytes of one decoded row of the channels sampled at every pixel (subsampled ones, fewer, left out).
std::uint64_t bytesPerRow(const Imf::Header& header, std::uint64_t width) {
  std::uint64_t bytes = 0;
  for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel)
    if (channel.channel().xSampling == 1 && channel.channel().ySampling == 1)
      bytes += channel.channel().type == Imf::HALF ? 2 : 4;
  return bytes * width;
}

// Size first: a tiled file needs at least an 8-byte offset and a 20-byte chunk header for each tile of
// its full-resolution level; a scan-line file's chunk table is checked whole (exr_chunk_table.hpp).
void checkPixelsFitTheFile(const std::string& path, const Imf::Header& header, int width, int height) {
  std::error_code error;
  const std::uint64_t fileBytes = std::filesystem::file_size(path, error);
  if (error) return;  // OpenEXR opened it: it will say what is wrong
  if (!header.hasTileDescription()) {
    const Imath::Box2i& window = header.dataWindow();
    checkExrScanLineChunks(
        path, fileBytes,
        {window.min.y, height, static_cast<std::int64_t>(linesPerChunk(header.compression())),
         bytesPerRow(header, static_cast<std::uint64_t>(width)), largestRatio(header.compression())});
    return;
  }
  const Imf::TileDescription& tiles = header.tileDescription();
  const std::uint64_t across =
      (static_cast<std::uint64_t>(width) + std::max(tiles.xSize, 1u) - 1) / std::max(tiles.xSize, 1u);
  const std::uint64_t down =
      (static_cast<std::uint64_t>(height) + std::max(tiles.ySize, 1u) - 1) / std::max(tiles.ySize, 1u);
  const std::uint64_t needed = across * down * (8 + 20);
  if (needed > fileBytes)
    throw InputError(
        SourceLocation{path},
        fmt::format("'{}' is truncated or corrupt: its header says {}x{} pixels in {} tiles, which "
                    "take at least {} bytes, but the file has {}",
                    path, width, height, across * down, needed, fileBytes));
}

// True for a grey image, luminance Y alone (as OpenEXR's RgbaOutputFile writes WRITE_Y): read as
// R = G = B = Y. Throws InputError for an image with neither R, G, B nor Y, and for luminance with
// chroma (RY, BY), which lancer does not convert.
bool greyOnly(const std::string& path, const Imf::ChannelList& channels) {
  if (channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B")) return false;
  if (channels.findChannel("RY") || channels.findChannel("BY"))
    throw InputError(SourceLocation{path},
                     fmt::format("'{}' holds luminance and chroma (Y, RY, BY); lancer reads "
                                 "R, G, B or Y alone: save it as RGB",
                                 path));
  if (channels.findChannel("Y")) return true;
  std::string names;
  for (auto channel = channels.begin(); channel != channels.end(); ++channel)
    names += (names.empty() ? "" : ", ") + std::string(channel.name());
  throw InputError(SourceLocation{path}, fmt::format("'{}' has no R, G, B or Y channel (its channels: {})",
                                                     path, names.empty() ? "none" : names));
}

}  // namespace

Image readExr(const std::string& path, ExrLayers* layers) {
  try {
    std::error_code error;
    if (const std::uint64_t fileBytes = std::filesystem::file_size(path, error); !error)
      checkExrHeaderSizes(path, fileBytes);  // before OpenEXR allocates what the header says
    Imf::InputFile in(path.c_str(), 1);
    const Imath::Box2i window = in.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
      throw InputError(SourceLocation{path}, fmt::format("unsupported EXR size {}x{}", width, height));
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    // Size first, memory second: the pixels the header claims must fit in the file, then in the budget.
    checkPixelsFitTheFile(path, in.header(), width, height);
    if (!in.isComplete())
      throw InputError(SourceLocation{path},
                       fmt::format("'{}' is incomplete: its table of chunks points past its end or at "
                                   "nothing (a truncated or corrupt file)",
                                   path));
    std::uint64_t bytesPerPixel = sizeof(Rgba);
    if (layers != nullptr) {
      const Imf::ChannelList& channels = in.header().channels();
      if (channels.findChannel("albedo.R") != nullptr) bytesPerPixel += sizeof(Vec3);
      if (channels.findChannel("normal.X") != nullptr) bytesPerPixel += sizeof(Vec3);
      if (channels.findChannel("Z") != nullptr) bytesPerPixel += sizeof(float);
    }
    requireMemory(saturatingProduct(pixels, bytesPerPixel), SourceLocation{path},
                  fmt::format("the {}x{} EXR image '{}'", width, height, path));
    Image image(width, height);
    // Slices are addressed from the data window's origin (OpenEXR's convention).
    const std::ptrdiff_t origin =
        static_cast<std::ptrdiff_t>(window.min.x) + static_cast<std::ptrdiff_t>(window.min.y) * width;
    Imf::FrameBuffer frame;
    char* base =
        reinterpret_cast<char*>(image.pixels().data()) - origin * static_cast<std::ptrdiff_t>(kRgbaStride);
    const Imf::ChannelList& channels = in.header().channels();
    const bool grey = greyOnly(path, channels);
    const char* names[4] = {grey ? "Y" : "R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
      if (!grey || c == 0 || c == 3)
        frame.insert(names[c], floatSlice(base + c * sizeof(float), kRgbaStride, kRgbaStride * width,
                                          c == 3 ? 1.0 : 0.0));
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
    if (grey)
      for (Rgba& pixel : image.pixels()) pixel.g = pixel.b = pixel.r;
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
void writeExr(const std::string& path, const Image&, const ExrLayers&, const ImageMetadata&) {
  unsupported(path);
}
Image readExr(const std::string& path, ExrLayers*) { unsupported(path); }

#endif

}  // namespace lancer
