#include "lancer/mesh/msh/foreign_formats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string_view>

namespace lancer {
namespace {

enum class Format { kNone, kGeo, kStep, kIges, kBrep, kVtk, kVtu, kOff, kUnv, kInp, kAnsys };

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

// The first line that is neither blank nor a comment starting with `comment`.
std::string_view firstStatement(std::string_view text, std::string_view comment) {
  std::string_view found;
  forEachLine(text, [&](std::string_view line) {
    if (found.empty() && !line.empty() && !(!comment.empty() && line.starts_with(comment))) found = line;
  });
  return found;
}

// OFF: "OFF" (or a variant: COFF, NOFF, STOFF, 4OFF, ...) alone on the first line.
bool looksLikeOff(std::string_view text) {
  std::string_view line = firstStatement(text, "#");
  line = line.substr(0, line.find_first_of("\r\n#"));
  while (!line.empty() && static_cast<unsigned char>(line.back()) <= ' ') line.remove_suffix(1);
  return line.size() >= 3 && line.size() <= 6 && line.ends_with("OFF") &&
         std::all_of(line.begin(), line.end(),
                     [](char c) { return std::isupper(static_cast<unsigned char>(c)) || c == '4'; });
}

// I-deas universal: datasets between lines of "-1", the first one's number on the line after it.
bool looksLikeUnv(std::string_view text) {
  int minusOnes = 0;
  bool datasetFollows = false, dataset = false;
  forEachLine(text, [&](std::string_view line) {
    while (!line.empty() && static_cast<unsigned char>(line.back()) <= ' ') line.remove_suffix(1);
    if (line == "-1") {
      ++minusOnes, datasetFollows = true;
      return;
    }
    if (datasetFollows && !line.empty() && std::all_of(line.begin(), line.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c));
        }))
      dataset = true;
    datasetFollows = false;
  });
  return minusOnes >= 1 && dataset && firstStatement(text, "").starts_with("-1");
}

// Abaqus input: keyword lines (*HEADING, *NODE, *PART, ...) and ** comments.
bool looksLikeInp(std::string_view text) {
  std::string line(firstStatement(text, "**").substr(0, 16));
  for (char& c : line) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const std::string_view keyword : {"*HEADING", "*NODE", "*ELEMENT", "*PART", "*PREPRINT", "*INCLUDE"})
    if (line.starts_with(keyword)) return true;
  return false;
}

// ANSYS Fluent mesh: S-expressions such as (1 "comment"), (0 "comment") or (2 3) from the first byte.
bool looksLikeAnsys(std::string_view text) {
  if (!text.starts_with("(")) return false;
  std::size_t digits = 1;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  return digits > 1 && digits < text.size() && (text[digits] == ' ' || text[digits] == '(');
}

Format byContent(std::string_view text) {
  const std::string_view start = trimmedStart(text);
  if (start.starts_with("ISO-10303-21")) return Format::kStep;
  if (start.starts_with("DBRep_DrawableShape") || start.starts_with("CASCADE Topology")) return Format::kBrep;
  if (start.starts_with("# vtk DataFile")) return Format::kVtk;
  if ((start.starts_with("<?xml") || start.starts_with("<VTKFile")) && text.find("<VTKFile") != text.npos)
    return Format::kVtu;
  if (looksLikeAnsys(text)) return Format::kAnsys;
  if (looksLikeOff(text)) return Format::kOff;
  if (looksLikeUnv(text)) return Format::kUnv;
  if (looksLikeInp(text)) return Format::kInp;
  // IGES: 80-column records with the section letter (S, G, ...) in column 73.
  if ((text.size() >= 81 && text[80] == '\n') || (text.size() >= 82 && text[80] == '\r')) {
    if (text[72] == 'S' && std::all_of(text.begin() + 73, text.begin() + 80, [](char c) {
          return c == ' ' || std::isdigit(static_cast<unsigned char>(c));
        }))
      return Format::kIges;
  }
  if (looksLikeGeo(text)) return Format::kGeo;
  return Format::kNone;
}

Format byExtension(const std::string& path) {
  const std::string extension = lower(std::filesystem::path(path).extension().string());
  if (extension == ".geo") return Format::kGeo;
  if (extension == ".step" || extension == ".stp") return Format::kStep;
  if (extension == ".iges" || extension == ".igs") return Format::kIges;
  if (extension == ".brep") return Format::kBrep;
  if (extension == ".vtk") return Format::kVtk;
  if (extension == ".vtu") return Format::kVtu;
  if (extension == ".off") return Format::kOff;
  if (extension == ".unv") return Format::kUnv;
  if (extension == ".inp") return Format::kInp;
  return Format::kNone;
}

const char* nativeExtension(Format format) {
  switch (format) {
    case Format::kGeo:
      return ".geo";
    case Format::kStep:
      return ".step";
    case Format::kIges:
      return ".iges";
    case Format::kBrep:
      return ".brep";
    case Format::kVtk:
      return ".vtk";
    case Format::kVtu:
      return ".vtu";
    case Format::kOff:
      return ".off";
    case Format::kUnv:
      return ".unv";
    case Format::kInp:
      return ".inp";
    case Format::kAnsys:
      return ".msh";
    case Format::kNone:
      break;
  }
  return nullptr;
}

// Formats gmsh 4.8 does not read (or, for VTK, only its own ASCII files): meshio's command, the
// reader named (meshio picks one by extension otherwise) and MSH 2.2 written, the one gmsh format
// meshio 7 writes for meshes of several element types without gmsh's entity data.
std::string meshioMessage(Format format, const std::string& path, const std::string& out) {
  struct Kind {
    Format format;
    const char* what;
    const char* reader;
  };
  static constexpr Kind kKinds[] = {{Format::kVtk, "a legacy VTK file", "vtk"},
                                    {Format::kVtu, "a VTK XML file (.vtu)", "vtu"},
                                    {Format::kOff, "an OFF surface", "off"},
                                    {Format::kInp, "an Abaqus input file (.inp)", "abaqus"},
                                    {Format::kAnsys, "an ANSYS Fluent mesh", "ansys"}};
  const Kind* kind = &kKinds[0];
  for (const Kind& k : kKinds)
    if (k.format == format) kind = &k;
  return fmt::format(
      "this is {}, not a gmsh mesh: convert it with meshio (Debian's python3-meshio): 'meshio convert {} {} "
      "--input-format {} --output-format gmsh22'",
      kind->what, path, out, kind->reader);
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
    case Format::kVtu:
    case Format::kOff:
    case Format::kInp:
    case Format::kAnsys:
      return meshioMessage(format, path, out);
    case Format::kUnv:
      return fmt::format(
          "this is an I-deas universal file (UNV), not a gmsh mesh: {}convert it with 'gmsh {} -save -o {}'",
          rename, path, out);
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

std::string foreignFileMessage(std::span<const char> head, const std::string& path) {
  const std::string_view text(head.data(), head.size());
  if (looksLikeMsh(head)) return {};
  Format format = byContent(text);
  if (format == Format::kNone) format = byExtension(path);
  if (format == Format::kNone) return {};
  // gmsh picks its reader by extension: a file recognised by content under another name is renamed
  // first. meshio is told the format, whatever the name; an ANSYS part.msh is converted to part_gmsh.msh.
  const bool meshio = format == Format::kVtk || format == Format::kVtu || format == Format::kOff ||
                      format == Format::kInp || format == Format::kAnsys;
  const bool renamed = byExtension(path) != format && !meshio;
  const std::string source =
      renamed ? std::filesystem::path(path).replace_extension(nativeExtension(format)).string() : path;
  const bool ontoItself = lower(std::filesystem::path(path).extension().string()) == ".msh";
  std::filesystem::path outPath(path);
  if (ontoItself) outPath.replace_filename(outPath.stem().string() + "_gmsh");
  const std::string out = outPath.replace_extension(".msh").string();
  return describe(format, text, source, out, renamed ? fmt::format("rename it to {}, then ", source) : "");
}

}  // namespace lancer
