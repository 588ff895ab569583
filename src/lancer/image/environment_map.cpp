#include "lancer/image/environment_map.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

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

}  // namespace

HdrImage readEnvironmentMap(const std::string& path) {
  unsigned char head[4] = {0, 0, 0, 0};
  std::streamsize read = 0;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw InputError(SourceLocation{path}, fmt::format("cannot open '{}': {}", path, std::strerror(errno)));
    in.read(reinterpret_cast<char*>(head), 4);
    read = in.gcount();
  }
  if (read == 4 && std::equal(head, head + 4, kExrMagic)) return fromExr(path);
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
