#include "lancer/image/image_metadata.hpp"

#include <fmt/format.h>

#include <cmath>

namespace lancer {

// LANCER_VERSION: CMake's project(VERSION), defined for this file in src/lancer/CMakeLists.txt.
std::string softwareName() { return "lancer " LANCER_VERSION; }

std::string quoteCommandLine(int argc, const char* const* argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    const std::string word = argv[i];
    if (!line.empty()) line += ' ';
    const bool plain =
        !word.empty() && word.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~!") == std::string::npos;
    if (plain) {
      line += word;
      continue;
    }
    line += '\'';
    for (const char c : word) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

void requireDpi(double dpi, const SourceLocation& where) {
  if (!(std::isfinite(dpi) && dpi > 0 && dpi <= kMaxDpi))
    throw InputError(where,
                     fmt::format("{} is not a resolution in dots per inch: give a number above 0 and at "
                                 "most {} (e.g. 300 for print)",
                                 dpi, kMaxDpi));
}

void requireImageQuality(long long quality, const SourceLocation& where) {
  if (quality < 1 || quality > 100)
    throw InputError(where, fmt::format("quality {} is out of range: use 1 (smallest file) to 100 (best "
                                        "picture); {} unless given",
                                        quality, kDefaultImageQuality));
}

std::uint32_t pixelsPerMetre(double dpi) { return static_cast<std::uint32_t>(std::lround(dpi / 0.0254)); }

namespace {

// TIFF 6.0, section 2: a 12-byte IFD entry (tag, type, count, value or offset), little-endian.
class TiffWriter {
 public:
  void u16(std::uint16_t v) {
    bytes.push_back(static_cast<std::uint8_t>(v));
    bytes.push_back(static_cast<std::uint8_t>(v >> 8));
  }
  void u32(std::uint32_t v) {
    u16(static_cast<std::uint16_t>(v));
    u16(static_cast<std::uint16_t>(v >> 16));
  }
  std::vector<std::uint8_t> bytes;
};

constexpr std::uint16_t kAscii = 2, kShort = 3, kRational = 5;

struct IfdEntry {
  std::uint16_t tag, type;
  std::vector<std::uint8_t> data;  // the value's bytes (little-endian), count derived from the type
};

}  // namespace

std::vector<std::uint8_t> exifBlock(const ImageMetadata& metadata) {
  if (metadata.empty()) return {};
  std::vector<IfdEntry> entries;  // in increasing tag order, as TIFF requires
  const auto ascii = [](const std::string& text) {
    std::vector<std::uint8_t> data(text.begin(), text.end());
    data.push_back(0);
    return data;
  };
  if (!metadata.command.empty())
    entries.push_back({0x010E, kAscii, ascii(metadata.command)});  // ImageDescription
  if (metadata.dpi > 0) {
    // A rational of the DPI in hundredths.
    TiffWriter rational;
    rational.u32(static_cast<std::uint32_t>(std::lround(metadata.dpi * 100)));
    rational.u32(100);
    entries.push_back({0x011A, kRational, rational.bytes});  // XResolution
    entries.push_back({0x011B, kRational, rational.bytes});  // YResolution
    entries.push_back({0x0128, kShort, {2, 0}});             // ResolutionUnit: inch
  }
  if (!metadata.software.empty()) entries.push_back({0x0131, kAscii, ascii(metadata.software)});  // Software
  TiffWriter out;
  out.bytes = {'I', 'I', 42, 0};
  out.u32(8);  // IFD0 right after the header
  out.u16(static_cast<std::uint16_t>(entries.size()));
  std::uint32_t dataOffset = 8 + 2 + 12 * static_cast<std::uint32_t>(entries.size()) + 4;
  std::vector<std::uint8_t> extra;
  for (const IfdEntry& entry : entries) {
    const std::uint32_t unit = entry.type == kRational ? 8 : (entry.type == kShort ? 2 : 1);
    out.u16(entry.tag);
    out.u16(entry.type);
    out.u32(static_cast<std::uint32_t>(entry.data.size()) / unit);
    if (entry.data.size() <= 4) {
      std::vector<std::uint8_t> value = entry.data;
      value.resize(4, 0);
      out.bytes.insert(out.bytes.end(), value.begin(), value.end());
    } else {
      out.u32(dataOffset + static_cast<std::uint32_t>(extra.size()));
      extra.insert(extra.end(), entry.data.begin(), entry.data.end());
      if (extra.size() % 2 != 0) extra.push_back(0);  // values start on a word boundary
    }
  }
  out.u32(0);  // no next IFD
  out.bytes.insert(out.bytes.end(), extra.begin(), extra.end());
  return out.bytes;
}

}  // namespace lancer
