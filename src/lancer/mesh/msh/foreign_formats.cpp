#include "lancer/mesh/msh/foreign_formats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <string_view>

namespace lancer {
namespace {

enum class Format { kNone, kGeo, kStlAscii, kStlBinary, kStep, kIges, kBrep, kVtk, kObj };

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string_view trimmedStart(std::string_view text) {
  while (!text.empty() && static_cast<unsigned char>(text.front()) <= ' ') text.remove_prefix(1);
  return text;
}

// The text's lines with comments (// and /* */ at line starts, # for OBJ-like formats) left in.
template <typename Fn>
void forEachLine(std::string_view text, Fn fn) {
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    fn(trimmedStart(text.substr(0, end)));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
}

bool startsWithWord(std::string_view line, std::string_view word) {
  if (!line.starts_with(word)) return false;
  line.remove_prefix(word.size());
  line = trimmedStart(line);
  return !line.empty() && (line.front() == '(' || line.front() == '"' || line.front() == '{');
}

// gmsh's .geo language: a statement like Point(1) = {...}; SetFactory("OpenCASCADE"); Merge "x";
bool looksLikeGeo(std::string_view text) {
  static constexpr std::string_view kWords[] = {"Point",
                                                "Line",
                                                "Curve",
                                                "Circle",
                                                "Spline",
                                                "Surface",
                                                "Plane Surface",
                                                "Volume",
                                                "Box",
                                                "Sphere",
                                                "Cylinder",
                                                "Rectangle",
                                                "Disk",
                                                "Torus",
                                                "Cone",
                                                "Wedge",
                                                "Merge",
                                                "Include",
                                                "SetFactory",
                                                "Physical",
                                                "Extrude",
                                                "BooleanUnion",
                                                "BooleanDifference",
                                                "BooleanFragments",
                                                "BooleanIntersection",
                                                "Transfinite",
                                                "Field",
                                                "ShapeFromFile",
                                                "Curve Loop",
                                                "Line Loop",
                                                "Surface Loop"};
  int statements = 0;
  forEachLine(text, [&](std::string_view line) {
    for (const std::string_view word : kWords)
      if (startsWithWord(line, word)) {
        ++statements;
        return;
      }
    if ((line.starts_with("Mesh.") || line.starts_with("Geometry.") || line.starts_with("General.")) &&
        line.find(';') != std::string_view::npos)
      ++statements;
  });
  return statements > 0;
}

bool looksLikeObj(std::string_view text) {
  int vertices = 0, other = 0;
  forEachLine(text, [&](std::string_view line) {
    if (line.empty() || line.front() == '#') return;
    if (line.starts_with("v ") || line.starts_with("vn ") || line.starts_with("vt ")) {
      ++vertices;
    } else if (!(line.starts_with("f ") || line.starts_with("o ") || line.starts_with("g ") ||
                 line.starts_with("s ") || line.starts_with("usemtl ") || line.starts_with("mtllib "))) {
      ++other;
    }
  });
  return vertices >= 3 && other == 0;
}

Format byContent(std::string_view text, std::uint64_t fileBytes) {
  const std::string_view start = trimmedStart(text);
  if (start.starts_with("ISO-10303-21")) return Format::kStep;
  if (start.starts_with("DBRep_DrawableShape") || start.starts_with("CASCADE Topology")) return Format::kBrep;
  if (start.starts_with("# vtk DataFile") ||
      (start.starts_with("<?xml") && text.find("<VTKFile") != text.npos))
    return Format::kVtk;
  if (start.starts_with("solid") && text.find("facet") != std::string_view::npos) return Format::kStlAscii;
  // Binary STL: an 80-byte header, a 32-bit triangle count, 50 bytes per triangle.
  if (text.size() >= 84) {
    std::uint32_t triangles;
    std::memcpy(&triangles, text.data() + 80, 4);
    if (fileBytes == 84 + 50 * std::uint64_t{triangles} && triangles > 0) return Format::kStlBinary;
  }
  // IGES: 80-column records with the section letter (S, G, ...) in column 73.
  if ((text.size() >= 81 && text[80] == '\n') || (text.size() >= 82 && text[80] == '\r')) {
    if (text[72] == 'S' && std::all_of(text.begin() + 73, text.begin() + 80, [](char c) {
          return c == ' ' || std::isdigit(static_cast<unsigned char>(c));
        }))
      return Format::kIges;
  }
  if (looksLikeGeo(text)) return Format::kGeo;
  if (looksLikeObj(text)) return Format::kObj;
  return Format::kNone;
}

Format byExtension(const std::string& path) {
  const std::string extension = lower(std::filesystem::path(path).extension().string());
  if (extension == ".geo") return Format::kGeo;
  if (extension == ".stl") return Format::kStlAscii;
  if (extension == ".step" || extension == ".stp") return Format::kStep;
  if (extension == ".iges" || extension == ".igs") return Format::kIges;
  if (extension == ".brep") return Format::kBrep;
  if (extension == ".vtk" || extension == ".vtu") return Format::kVtk;
  if (extension == ".obj") return Format::kObj;
  return Format::kNone;
}

const char* nativeExtension(Format format) {
  switch (format) {
    case Format::kGeo:
      return ".geo";
    case Format::kStlAscii:
    case Format::kStlBinary:
      return ".stl";
    case Format::kStep:
      return ".step";
    case Format::kIges:
      return ".iges";
    case Format::kBrep:
      return ".brep";
    case Format::kVtk:
      return ".vtk";
    case Format::kObj:
      return ".obj";
    case Format::kNone:
      break;
  }
  return nullptr;
}

// The message for a file of `format` at `path` (renamed to its native extension when `rename` says
// so); out: the .msh to write.
std::string describe(Format format, std::string_view text, const std::string& path, const std::string& out,
                     const std::string& rename) {
  switch (format) {
    case Format::kGeo: {
      // A script that makes volumes wants -3; otherwise surfaces are what lancer draws.
      const bool volumes = text.find("Volume") != std::string_view::npos || text.find("Box(") != text.npos ||
                           text.find("Sphere(") != text.npos || text.find("Cylinder(") != text.npos;
      return fmt::format(
          "this is a gmsh geometry script (.geo), not a mesh: {}mesh it with 'gmsh {} -{} -o {}'", rename,
          path, volumes ? 3 : 2, out);
    }
    case Format::kStlAscii:
    case Format::kStlBinary:
      return fmt::format(
          "this is an STL surface ({}), not a gmsh mesh: {}convert it with 'gmsh {} -save -o {}'",
          format == Format::kStlBinary ? "binary" : "ASCII", rename, path, out);
    case Format::kStep:
      return fmt::format(
          "this is a STEP CAD model, not a mesh: {}mesh it with 'gmsh {} -2 -o {}' (-3 to mesh "
          "its volumes)",
          rename, path, out);
    case Format::kIges:
      return fmt::format("this is an IGES CAD model, not a mesh: {}mesh it with 'gmsh {} -2 -o {}'", rename,
                         path, out);
    case Format::kBrep:
      return fmt::format("this is an OpenCASCADE BREP model, not a mesh: {}mesh it with 'gmsh {} -2 -o {}'",
                         rename, path, out);
    case Format::kVtk:
      return fmt::format("this is a VTK file, not a gmsh mesh: {}convert it with 'gmsh {} -save -o {}'",
                         rename, path, out);
    case Format::kObj:
      return fmt::format(
          "this is a Wavefront OBJ mesh, which gmsh does not read: convert it, e.g. with "
          "meshio: 'meshio convert {} {}'",
          path, out);
    case Format::kNone:
      break;
  }
  return {};
}

}  // namespace

bool looksLikeMsh(std::span<const char> head) {
  const std::string_view start = trimmedStart({head.data(), head.size()});
  return start.starts_with("$MeshFormat") || start.starts_with("$NOD") || start.starts_with("$NOE");
}

std::string foreignFileMessage(std::span<const char> head, std::uint64_t fileBytes, const std::string& path) {
  const std::string_view text(head.data(), head.size());
  if (looksLikeMsh(head)) return {};
  Format format = byContent(text, fileBytes);
  if (format == Format::kNone) format = byExtension(path);
  if (format == Format::kNone) return {};
  // gmsh picks its reader by extension: a file recognised by content under another name is renamed
  // first (and an STL named part.msh is not converted onto itself). meshio reads OBJ by content.
  const std::string extension = lower(std::filesystem::path(path).extension().string());
  const bool renamed = byExtension(path) != format && format != Format::kObj &&
                       !(format == Format::kStlBinary && extension == ".stl");
  const std::string source =
      renamed ? std::filesystem::path(path).replace_extension(nativeExtension(format)).string() : path;
  const std::string out = std::filesystem::path(path).replace_extension(".msh").string();
  return describe(format, text, source, out, renamed ? fmt::format("rename it to {}, then ", source) : "");
}

}  // namespace lancer
