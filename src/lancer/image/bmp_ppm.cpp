// BMP and PPM: formats simple enough that lancer writes them itself.
// BMP layout from Microsoft's BITMAPFILEHEADER / BITMAPINFOHEADER documentation (all little-endian).
#include <fmt/format.h>

#include <limits>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

void putLe16(std::vector<std::uint8_t>& out, std::uint32_t v) {
  out.push_back(static_cast<std::uint8_t>(v));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void putLe32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  putLe16(out, v & 0xffffu);
  putLe16(out, v >> 16);
}

constexpr std::uint32_t kBmpHeaderSize = 14 + 40;
constexpr std::uint32_t kPixelsPerMetre = 2835;  // 72 dpi

}  // namespace

std::vector<std::uint8_t> encodeBmp(const Image& image, TransferCurve curve) {
  const std::uint64_t width = static_cast<std::uint64_t>(image.width());
  const std::uint64_t stride = (width * 3 + 3) / 4 * 4;
  const std::uint64_t pixelBytes = stride * static_cast<std::uint64_t>(image.height());
  if (pixelBytes + kBmpHeaderSize > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(SourceLocation{},
                     fmt::format("a {}x{} image is too large for BMP (4 GiB at most); use .png",
                                 image.width(), image.height()));
  }
  std::vector<std::uint8_t> out;
  out.reserve(static_cast<std::size_t>(kBmpHeaderSize + pixelBytes));
  out.push_back('B');
  out.push_back('M');
  putLe32(out, static_cast<std::uint32_t>(kBmpHeaderSize + pixelBytes));  // file size
  putLe32(out, 0);                                                        // two reserved words
  putLe32(out, kBmpHeaderSize);                                           // offset of the pixels
  putLe32(out, 40);                                                       // BITMAPINFOHEADER size
  putLe32(out, static_cast<std::uint32_t>(image.width()));
  putLe32(out, static_cast<std::uint32_t>(image.height()));  // positive: rows stored bottom-up
  putLe16(out, 1);                                           // planes
  putLe16(out, 24);                                          // bits per pixel
  putLe32(out, 0);                                           // BI_RGB, uncompressed
  putLe32(out, static_cast<std::uint32_t>(pixelBytes));
  putLe32(out, kPixelsPerMetre);
  putLe32(out, kPixelsPerMetre);
  putLe32(out, 0);  // colours used
  putLe32(out, 0);  // important colours
  const std::size_t padding = static_cast<std::size_t>(stride - width * 3);
  for (int y = image.height() - 1; y >= 0; --y) {
    for (const Rgba& p : image.row(y)) {
      out.push_back(encode8(p.b, curve));
      out.push_back(encode8(p.g, curve));
      out.push_back(encode8(p.r, curve));
    }
    out.insert(out.end(), padding, 0);
  }
  return out;
}

std::vector<std::uint8_t> encodePpm(const Image& image, TransferCurve curve) {
  const std::string header = fmt::format("P6\n{} {}\n255\n", image.width(), image.height());
  std::vector<std::uint8_t> out(header.begin(), header.end());
  const std::vector<std::uint8_t> samples = encodeImage8(image, curve, 3);
  out.insert(out.end(), samples.begin(), samples.end());
  return out;
}

void writeBmp(const std::string& path, const Image& image, TransferCurve curve) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = encodeBmp(image, curve);
  } catch (const InputError& e) {
    throw InputError(SourceLocation{path}, e.message());
  }
  writeFileAtomically(path, bytes);
}

void writePpm(const std::string& path, const Image& image, TransferCurve curve) {
  writeFileAtomically(path, encodePpm(image, curve));
}

}  // namespace lancer
