#include "lancer/image/environment_map.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "lancer/image/exr_io.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// OpenEXR's magic number, the file's first four bytes (OpenEXR file layout, "Magic Number").
constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};

bool endsWithExr(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return std::tolower(c); });
  return tail == ".exr";
}

HdrImage fromExr(const std::string& path) {
  const Image image = readExr(path);
  HdrImage map;
  map.width = image.width();
  map.height = image.height();
  map.pixels.reserve(static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height));
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const Rgba& p = image.at(x, y);
      if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b))
        throw InputError(SourceLocation{path},
                         fmt::format("'{}' has a non-finite value ({}, {}, {}) at pixel ({}, {}); an "
                                     "environment map holds radiance: finite values >= 0",
                                     path, p.r, p.g, p.b, x, y));
      map.pixels.push_back({std::max(p.r, 0.0f), std::max(p.g, 0.0f), std::max(p.b, 0.0f)});
    }
  return map;
}

// What a file that is no map is, from its first bytes (each format's signature): "" when unknown.
std::string_view otherFormatOf(std::string_view head) {
  const auto starts = [&](std::string_view magic) { return head.starts_with(magic); };
  if (starts("\x89PNG\r\n\x1a\n")) return "a PNG image";
  if (starts("\xff\xd8\xff")) return "a JPEG image";
  if (starts("GIF87a") || starts("GIF89a")) return "a GIF image";
  if (starts("II*\0") || starts("MM\0*")) return "a TIFF image";
  if (starts("BM")) return "a BMP image";
  if (head.size() >= 3 && head[0] == 'P' && head[1] >= '1' && head[1] <= '6' && std::isspace(head[2]))
    return "a PPM/PGM image";
  if (starts("$MeshFormat")) return "a gmsh mesh";
  return "";
}

}  // namespace

HdrImage readEnvironmentMap(const std::string& path) {
  if (std::filesystem::is_directory(path))
    throw InputError(SourceLocation{path}, fmt::format("'{}' is a folder, not a map file", path));
  char bytes[16] = {};
  std::streamsize read = 0;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw InputError(SourceLocation{path}, fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
    in.read(bytes, sizeof bytes);
    read = in.gcount();
  }
  const std::string_view start(bytes, static_cast<std::size_t>(read));
  if (const std::string_view other = otherFormatOf(start); !other.empty())
    throw InputError(SourceLocation{path},
                     fmt::format("'{}' is {}, not a Radiance .hdr or OpenEXR map (an environment map is an "
                                 "equirectangular image of radiance, e.g. 2048 x 1024)",
                                 path, other));
  const auto* head = reinterpret_cast<const unsigned char*>(bytes);
  if (read >= 4 && std::equal(head, head + 4, kExrMagic)) return fromExr(path);
  if (endsWithExr(path) && read < 4)
    throw InputError(SourceLocation{path},
                     fmt::format("'{}' is not an OpenEXR image: it is {} bytes long", path, read));
  if (endsWithExr(path))
    throw InputError(SourceLocation{path},
                     fmt::format("'{}' is not an OpenEXR image: its first bytes are {:02x}, where an EXR "
                                 "file starts with 76 2f 31 01",
                                 path, fmt::join(head, head + 4, " ")));
  return readRadianceHdr(path);
}

}  // namespace lancer
