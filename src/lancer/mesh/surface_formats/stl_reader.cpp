#include "lancer/mesh/surface_formats/stl_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>

#include "lancer/mesh/msh/text_number.hpp"
#include "lancer/mesh/surface_formats/surface_mesh.hpp"
#include "lancer/mesh/surface_formats/text_lines.hpp"
#include "lancer/util/memory_budget.hpp"

namespace lancer {
namespace {

constexpr std::uint64_t kBinaryHeaderBytes = 84;    // 80 bytes of text, a 32-bit triangle count
constexpr std::uint64_t kBinaryTriangleBytes = 50;  // normal, three corners (12 floats), 16-bit attribute
// What a triangle takes while it is read: three points (24 bytes each), their welded indices and the
// weld's hash table, the assembler's face after it.
constexpr std::uint64_t kTriangleMemoryBytes = 200;

bool equalsIgnoringCase(std::string_view text, std::string_view word) {
  return text.size() == word.size() && std::equal(text.begin(), text.end(), word.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

std::uint32_t binaryTriangleCount(std::span<const char> bytes) {
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  if constexpr (std::endian::native == std::endian::big) count = __builtin_bswap32(count);
  return count;
}

float littleEndianFloat(const char* at) {
  std::uint32_t bits;
  std::memcpy(&bits, at, 4);
  if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap32(bits);
  return std::bit_cast<float>(bits);
}

// The facets' corners (three points each, as the file lists them) welded into shared points.
void weldTriangles(SurfaceData& data) {
  const std::vector<std::uint32_t> index = weldPoints(data.points);
  for (SurfaceGroup& group : data.groups)
    for (std::uint32_t& corner : group.triangles) corner = index[corner];
}

// The text of a block's header up to its first NUL, when it is all printable: gmsh writes a block per
// physical surface with the surface's name there.
std::string headerName(const char* header) {
  std::string_view text(header, 80);
  text = text.substr(0, text.find('\0'));
  while (!text.empty() && isTextSpace(text.back())) text.remove_suffix(1);
  while (!text.empty() && isTextSpace(text.front())) text.remove_prefix(1);
  const bool printable = std::all_of(text.begin(), text.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 32 && static_cast<unsigned char>(c) < 127;
  });
  return printable ? std::string(text) : std::string();
}

// A binary STL is one block (an 80-byte header, a triangle count, the triangles) or several one after
// the other, as gmsh writes one per physical surface: each block is a group, named after its header
// when there are several.
Mesh readBinary(std::span<const char> bytes, const std::string& name) {
  if (bytes.size() < kBinaryHeaderBytes)
    throw InputError(
        SourceLocation{name},
        fmt::format("a binary STL starts with an 84-byte header, but the file has {} bytes (it is "
                    "truncated, or not an STL: an ASCII STL starts with 'solid')",
                    bytes.size()));
  MeshSourceInfo source;
  source.path = name;
  source.format = "stl";
  source.binary = true;
  source.fileBytes = bytes.size();
  // The blocks, checked against the file's size before anything is allocated.
  struct Block {
    std::uint64_t start;
    std::uint64_t count;
  };
  std::vector<Block> blocks;
  std::uint64_t total = 0;
  for (std::uint64_t at = 0; at < bytes.size();) {
    const std::uint64_t remaining = bytes.size() - at;
    if (!blocks.empty() && remaining < kBinaryHeaderBytes) {
      source.warnings.push_back(formatInputWarning(
          SourceLocation{name, 0, 0, static_cast<std::int64_t>(at)},
          fmt::format("{} bytes after the last block of triangles are ignored", remaining)));
      break;
    }
    const std::uint64_t count = binaryTriangleCount(bytes.subspan(at));
    const std::uint64_t blockBytes = kBinaryHeaderBytes + kBinaryTriangleBytes * count;
    if (blockBytes > remaining)
      throw InputError(
          SourceLocation{name, 0, 0, static_cast<std::int64_t>(at + 80)},
          fmt::format("the binary STL header declares {} triangles ({} bytes with the header), but "
                      "{} bytes remain in the file (truncated, or not an STL: an ASCII STL starts "
                      "with 'solid')",
                      count, blockBytes, remaining));
    blocks.push_back(Block{at, count});
    total += count;
    at += blockBytes;
  }
  requireMemory(saturatingProduct(total, kTriangleMemoryBytes), SourceLocation{name},
                fmt::format("an STL of {} triangles", total));
  if (3 * total > UINT32_MAX)
    throw InputError(SourceLocation{name}, fmt::format("{} triangles: too many for lancer", total));
  SurfaceData data;
  data.points.reserve(3 * total);
  for (const Block& block : blocks) {
    SurfaceGroup& group = data.group(blocks.size() > 1 ? headerName(bytes.data() + block.start) : "");
    group.triangles.reserve(group.triangles.size() + 3 * block.count);
    for (std::uint64_t t = 0; t < block.count; ++t) {
      const char* record = bytes.data() + block.start + kBinaryHeaderBytes + kBinaryTriangleBytes * t;
      for (int corner = 0; corner < 3; ++corner) {
        const char* at = record + 12 + 12 * corner;
        const Vec3d p{littleEndianFloat(at), littleEndianFloat(at + 4), littleEndianFloat(at + 8)};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
          throw InputError(SourceLocation{name, 0, 0, at - bytes.data()},
                           fmt::format("a triangle has a non-finite corner ({}, {}, {})", p.x, p.y, p.z));
        group.triangles.push_back(static_cast<std::uint32_t>(data.points.size()));
        data.points.push_back(p);
      }
    }
  }
  weldTriangles(data);
  return meshFromSurface(data, std::move(source));
}

// solid NAME / facet normal n n n / outer loop / vertex x y z (three or more) / endloop / endfacet /
// endsolid NAME, keywords in any case; a loop of more than three vertices is split into a fan.
Mesh readAscii(std::span<const char> bytes, const std::string& name) {
  TextLines lines(bytes, name);
  SurfaceData data;
  SurfaceGroup* solid = nullptr;
  bool inFacet = false;
  std::size_t facetStart = 0;  // the facet's first point
  while (lines.nextLine()) {
    const std::string_view keyword = lines.token();
    if (keyword.empty()) continue;
    if (equalsIgnoringCase(keyword, "solid")) {
      if (solid) lines.fail("'solid' inside a solid: the one before has no 'endsolid'");
      solid = &data.group(lines.restOfLine());
    } else if (equalsIgnoringCase(keyword, "endsolid")) {
      if (!solid) lines.fail("'endsolid' without a 'solid' before it");
      if (inFacet) lines.fail("'endsolid' inside a facet: expected 'endfacet' first");
      solid = nullptr;
    } else if (equalsIgnoringCase(keyword, "facet")) {
      if (!solid) lines.fail("'facet' outside a solid: an ASCII STL starts with 'solid NAME'");
      if (inFacet) lines.fail("'facet' inside a facet: the one before has no 'endfacet'");
      inFacet = true;
      facetStart = data.points.size();
    } else if (equalsIgnoringCase(keyword, "vertex")) {
      if (!inFacet) lines.fail("'vertex' outside a facet");
      Vec3d p;
      p.x = lines.readNumber("the x coordinate of a vertex");
      p.y = lines.readNumber("the y coordinate of a vertex");
      p.z = lines.readNumber("the z coordinate of a vertex");
      if (!lines.atLineEnd())
        lines.fail(fmt::format("unexpected {} after a vertex's three coordinates",
                               quoteTokenForMessage(lines.token())));
      data.points.push_back(p);
    } else if (equalsIgnoringCase(keyword, "endfacet")) {
      if (!inFacet) lines.fail("'endfacet' without a 'facet' before it");
      const std::size_t corners = data.points.size() - facetStart;
      if (corners < 3) lines.fail(fmt::format("a facet with {} vertices: a facet needs at least 3", corners));
      for (std::size_t k = 1; k + 1 < corners; ++k)
        for (const std::size_t corner : {facetStart, facetStart + k, facetStart + k + 1})
          solid->triangles.push_back(static_cast<std::uint32_t>(corner));
      inFacet = false;
    } else if (equalsIgnoringCase(keyword, "outer") || equalsIgnoringCase(keyword, "endloop")) {
      if (!inFacet) lines.fail(fmt::format("'{}' outside a facet", keyword));
    } else {
      lines.fail(
          fmt::format("expected an STL keyword (solid, facet, outer loop, vertex, endloop, endfacet, "
                      "endsolid), found {}",
                      quoteTokenForMessage(keyword)));
    }
    if (data.points.size() > UINT32_MAX - 3) lines.fail("more than 4294967292 vertices: too many for lancer");
  }
  if (inFacet) lines.failAtEnd("the file ends inside a facet (it looks truncated)");
  if (solid) lines.failAtEnd("the file ends before 'endsolid' (it looks truncated)");
  weldTriangles(data);
  MeshSourceInfo source;
  source.path = name;
  source.format = "stl";
  source.fileBytes = bytes.size();
  return meshFromSurface(data, std::move(source));
}

}  // namespace

StlKind stlKindOf(std::span<const char> head, std::uint64_t fileBytes) {
  if (head.size() >= kBinaryHeaderBytes &&
      fileBytes == kBinaryHeaderBytes + kBinaryTriangleBytes * std::uint64_t{binaryTriangleCount(head)})
    return StlKind::kBinary;
  std::string_view text(head.data(), head.size());
  while (!text.empty() && isTextSpace(text.front())) text.remove_prefix(1);
  if (text.size() < 5 || !equalsIgnoringCase(text.substr(0, 5), "solid")) return StlKind::kNone;
  if (text.size() > 5 && !isTextSpace(text[5])) return StlKind::kNone;
  // Text: no byte below a blank but tabs and line ends (a binary header that says "solid" has floats
  // after it, whose bytes are such somewhere in the first kilobytes).
  const bool binaryBytes = std::any_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 32 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v';
  });
  return binaryBytes ? StlKind::kBinary : StlKind::kAscii;
}

Mesh readStl(std::span<const char> bytes, const std::string& name, StlKind kind) {
  return kind == StlKind::kAscii ? readAscii(bytes, name) : readBinary(bytes, name);
}

}  // namespace lancer
