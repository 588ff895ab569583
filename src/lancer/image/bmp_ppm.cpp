// BMP and PPM: formats simple enough that lancer writes them itself.
// BMP layout from Microsoft's BITMAPFILEHEADER / BITMAPINFOHEADER documentation (all little-endian).
#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/bmp_ppm_layout.hpp"
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

std::uint64_t bmpRowBytes(int width) { return (static_cast<std::uint64_t>(width) * 3 + 3) / 4 * 4; }

std::vector<std::uint8_t> bmpHeader(int width, int height) {
  const std::uint64_t pixelBytes = bmpRowBytes(width) * static_cast<std::uint64_t>(height);
  if (pixelBytes + kBmpHeaderSize > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(
        SourceLocation{},
        fmt::format("a {}x{} image is too large for BMP (4 GiB at most); use .png", width, height));
  }
  std::vector<std::uint8_t> out;
  out.reserve(kBmpHeaderSize);
  out.push_back('B');
  out.push_back('M');
  putLe32(out, static_cast<std::uint32_t>(kBmpHeaderSize + pixelBytes));  // file size
  putLe32(out, 0);                                                        // two reserved words
  putLe32(out, kBmpHeaderSize);                                           // offset of the pixels
  putLe32(out, 40);                                                       // BITMAPINFOHEADER size
  putLe32(out, static_cast<std::uint32_t>(width));
  putLe32(out, static_cast<std::uint32_t>(height));  // positive: rows stored bottom-up
  putLe16(out, 1);                                   // planes
  putLe16(out, 24);                                  // bits per pixel
  putLe32(out, 0);                                   // BI_RGB, uncompressed
  putLe32(out, static_cast<std::uint32_t>(pixelBytes));
  putLe32(out, kPixelsPerMetre);
  putLe32(out, kPixelsPerMetre);
  putLe32(out, 0);  // colours used
  putLe32(out, 0);  // important colours
  return out;
}

void encodeBmpRow(std::span<const Rgba> row, TransferCurve curve, std::uint8_t* out) {
  std::uint8_t* const begin = out;
  for (const Rgba& p : row) {
    *out++ = encode8(p.b, curve);
    *out++ = encode8(p.g, curve);
    *out++ = encode8(p.r, curve);
  }
  const std::uint64_t padded = bmpRowBytes(static_cast<int>(row.size()));
  std::fill(out, begin + padded, std::uint8_t{0});
}

std::string ppmHeader(int width, int height) { return fmt::format("P6\n{} {}\n255\n", width, height); }

std::vector<std::uint8_t> encodeBmp(const Image& image, TransferCurve curve) {
  std::vector<std::uint8_t> out = bmpHeader(image.width(), image.height());
  const std::size_t stride = static_cast<std::size_t>(bmpRowBytes(image.width()));
  out.resize(out.size() + stride * static_cast<std::size_t>(image.height()));
  std::uint8_t* row = out.data() + kBmpHeaderSize;
  for (int y = image.height() - 1; y >= 0; --y, row += stride) encodeBmpRow(image.row(y), curve, row);
  return out;
}

std::vector<std::uint8_t> encodePpm(const Image& image, TransferCurve curve) {
  const std::string header = ppmHeader(image.width(), image.height());
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
