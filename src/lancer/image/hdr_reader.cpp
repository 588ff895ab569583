#include "lancer/image/hdr_reader.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "lancer/util/input_error.hpp"
#include "lancer/util/memory_budget.hpp"

namespace lancer {
namespace {

Vec3 fromRgbe(const unsigned char* rgbe) {
  if (rgbe[3] == 0) return {0, 0, 0};
  const float scale = std::ldexp(1.0f, static_cast<int>(rgbe[3]) - (128 + 8));
  return {(static_cast<float>(rgbe[0]) + 0.5f) * scale, (static_cast<float>(rgbe[1]) + 0.5f) * scale,
          (static_cast<float>(rgbe[2]) + 0.5f) * scale};
}

constexpr long long kMaxPixels = 1LL << 28;

// Bytes of a file quoted in a message: printable ASCII as it is, anything else as \xNN, so that a
// message about a binary file stays one line of valid text.
std::string printable(std::string_view bytes) {
  std::string text;
  for (const char c : bytes) {
    if (c >= 0x20 && c < 0x7f && c != '\\')
      text += c;
    else
      text += fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
  }
  return text;
}

}  // namespace

HdrImage readRadianceHdr(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(SourceLocation{path}, fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad())
    throw InputError(SourceLocation{path}, fmt::format("cannot read '{}': {}", path, std::strerror(errno)));
  return decodeRadianceHdr(bytes.str(), path);
}

HdrImage decodeRadianceHdr(const std::string& bytes, const std::string& path) {
  auto fail = [&](const std::string& what) -> HdrImage {
    throw InputError(SourceLocation{path}, fmt::format("'{}' is not a Radiance .hdr image: {}", path, what));
  };
  std::size_t at = 0;
  auto line = [&](std::string& text) {
    const std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) return false;
    text = bytes.substr(at, end - at);
    at = end + 1;
    return true;
  };
  std::string text;
  if (!line(text) || !(text.starts_with("#?RADIANCE") || text.starts_with("#?RGBE")))
    return fail(fmt::format("the first line is \"{}\", expected #?RADIANCE",
                            printable(bytes.substr(0, std::min<std::size_t>(bytes.find('\n'), 40)))));
  for (;;) {
    if (!line(text)) return fail("the header does not end (no empty line before the size)");
    if (text.empty()) break;
    if (text.starts_with("FORMAT=") && text != "FORMAT=32-bit_rle_rgbe")
      return fail(fmt::format("{} (only 32-bit_rle_rgbe is read)", printable(text.substr(0, 60))));
  }
  if (!line(text)) return fail("no size line after the header");
  HdrImage image;
  // "-Y height +X width": rows top to bottom, columns left to right (the only orientation read).
  auto number = [&](std::string_view field, int& value) {
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    return error == std::errc() && end == field.data() + field.size();
  };
  std::istringstream fields(text);
  std::string yAxis, height, xAxis, width, extra;
  fields >> yAxis >> height >> xAxis >> width;
  if (yAxis != "-Y" || xAxis != "+X" || !number(height, image.height) || !number(width, image.width) ||
      (fields >> extra))
    return fail(fmt::format("the size line is \"{}\", expected \"-Y height +X width\"",
                            printable(text.substr(0, 60))));
  if (image.width <= 0 || image.height <= 0 ||
      static_cast<long long>(image.width) * image.height > kMaxPixels)
    return fail(fmt::format("size {} x {} is out of range", image.width, image.height));
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t size = bytes.size();
  // Size first, memory second: every scanline takes some bytes of the file (a run-length one at least
  // its 4-byte start and a 2-byte run per 127 pixels of each of its 4 channels, a flat one 4 bytes a
  // pixel), so a size the file cannot hold is refused before the pixels are allocated.
  const std::uint64_t pixelCount = static_cast<std::uint64_t>(image.width) * image.height;
  const std::uint64_t scanlineBytes =
      image.width >= 8 && image.width < 32768
          ? 4 + 4 * 2 * ((static_cast<std::uint64_t>(image.width) + 126) / 127)
          : 4 * static_cast<std::uint64_t>(image.width);
  if (scanlineBytes * image.height > size - at)
    throw InputError(SourceLocation{path, 0, 0, static_cast<std::int64_t>(at)},
                     fmt::format("'{}' is truncated or its size is corrupt: {} x {} pixels take at least {} "
                                 "bytes of scanlines, but only {} bytes follow the size line",
                                 path, image.width, image.height, scanlineBytes * image.height, size - at));
  requireMemory(pixelCount * sizeof(Vec3), SourceLocation{path},
                fmt::format("the {} x {} map in '{}'", image.width, image.height, path));
  image.pixels.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  std::vector<unsigned char> scan(static_cast<std::size_t>(image.width) * 4);
  for (int y = 0; y < image.height; ++y) {
    const bool rle = image.width >= 8 && image.width < 32768 && at + 4 <= size && data[at] == 2 &&
                     data[at + 1] == 2 && (data[at + 2] & 0x80) == 0;
    if (rle) {
      if (((data[at + 2] << 8) | data[at + 3]) != image.width)
        return fail(fmt::format("scanline {} says its width is {}, the image's is {}", y,
                                (data[at + 2] << 8) | data[at + 3], image.width));
      at += 4;
      for (int channel = 0; channel < 4; ++channel) {
        for (int x = 0; x < image.width;) {
          if (at >= size) return fail(fmt::format("the data ends in scanline {} of {}", y, image.height));
          int count = data[at++];
          const bool run = count > 128;
          if (run) count -= 128;
          if (count == 0 || x + count > image.width || at + (run ? 1 : count) > size)
            return fail(fmt::format("a bad run in scanline {}", y));
          for (int i = 0; i < count; ++i, ++x)
            scan[static_cast<std::size_t>(x) * 4 + channel] = run ? data[at] : data[at + i];
          at += run ? 1 : count;
        }
      }
    } else {
      if (at + scan.size() > size)
        return fail(fmt::format("the data ends in scanline {} of {}", y, image.height));
      std::memcpy(scan.data(), data + at, scan.size());
      at += scan.size();
    }
    for (int x = 0; x < image.width; ++x)
      image.pixels[static_cast<std::size_t>(y) * image.width + x] =
          fromRgbe(&scan[static_cast<std::size_t>(x) * 4]);
  }
  return image;
}

}  // namespace lancer
