#include "lancer/mesh/surface_formats/ply_header.hpp"

#include <fmt/format.h>

#include <optional>
#include <string_view>

#include "lancer/mesh/msh/text_number.hpp"
#include "lancer/mesh/surface_formats/text_lines.hpp"

namespace lancer {
namespace {

// PLY's type names, the original ones and the sized ones later writers use.
std::optional<PlyType> plyTypeNamed(std::string_view name) {
  struct Name {
    std::string_view name;
    PlyType type;
  };
  static constexpr Name kNames[] = {
      {"char", PlyType::kInt8},      {"int8", PlyType::kInt8},       {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},    {"short", PlyType::kInt16},     {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16},  {"uint16", PlyType::kUint16},   {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},    {"uint", PlyType::kUint32},     {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32},  {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64}};
  for (const Name& entry : kNames)
    if (entry.name == name) return entry.type;
  return std::nullopt;
}

// The type the token just read names; an error at it when it names none.
PlyType typeOrFail(TextLines& lines, std::string_view name) {
  const std::optional<PlyType> type = plyTypeNamed(name);
  if (!type)
    lines.fail(
        fmt::format("unknown property type {}: PLY's types are char, uchar, short, ushort, int, uint, "
                    "float, double (or int8, uint8, int16, uint16, int32, uint32, float32, float64)",
                    quoteTokenForMessage(name)));
  return *type;
}

PlyType readType(TextLines& lines, const char* what) {
  const std::string_view name = lines.token();
  if (name.empty()) lines.fail(fmt::format("expected {}, found the end of the line", what));
  return typeOrFail(lines, name);
}

}  // namespace

int plyTypeBytes(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      break;
  }
  return 8;
}

bool isPlyIntegerType(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

std::uint64_t PlyElement::minimumBinaryBytes() const {
  std::uint64_t bytes = 0;
  for (const PlyProperty& property : properties)
    bytes += static_cast<std::uint64_t>(plyTypeBytes(property.list ? property.countType : property.type));
  return bytes;
}

int PlyElement::find(std::string_view wanted) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == wanted) return static_cast<int>(i);
  return -1;
}

bool looksLikePly(std::span<const char> head) {
  const std::string_view text(head.data(), head.size());
  return text.starts_with("ply\n") || text.starts_with("ply\r\n");
}

PlyHeader readPlyHeader(std::span<const char> bytes, const std::string& name) {
  TextLines lines(bytes, name);
  PlyHeader header;
  lines.nextLine();
  if (lines.token() != "ply" || !lines.atLineEnd()) lines.failAtLine("not a PLY file: it starts with 'ply'");
  bool formatSeen = false;
  for (;;) {
    if (!lines.nextLine())
      lines.failAtEnd("the PLY header has no end_header line (the file is truncated or not a PLY file)");
    const std::string_view keyword = lines.token();
    if (keyword == "end_header") {
      header.dataOffset = lines.nextLineOffset();
      header.dataLine = lines.lineNumber() + 1;
      break;
    }
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "format") {
      const std::string_view format = lines.token();
      if (format == "ascii") {
        header.format = PlyHeader::Format::kAscii;
      } else if (format == "binary_little_endian") {
        header.format = PlyHeader::Format::kBinaryLittleEndian;
      } else if (format == "binary_big_endian") {
        header.format = PlyHeader::Format::kBinaryBigEndian;
      } else {
        lines.fail(
            fmt::format("unknown PLY format {}: expected ascii, binary_little_endian or "
                        "binary_big_endian",
                        quoteTokenForMessage(format)));
      }
      const std::string_view version = lines.token();
      if (version != "1.0" && version != "1")
        lines.fail(fmt::format("PLY version {}: lancer reads version 1.0", quoteTokenForMessage(version)));
      formatSeen = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(lines.token());
      if (element.name.empty()) lines.fail("expected the element's name, found the end of the line");
      const std::int64_t count = lines.readInteger("the element's count");
      if (count < 0) lines.fail(fmt::format("element {} has a negative count ({})", element.name, count));
      element.count = static_cast<std::uint64_t>(count);
      element.line = lines.lineNumber();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) lines.failAtLine("a property before any element");
      PlyProperty property;
      const std::string_view kind = lines.token();
      if (kind == "list") {
        property.list = true;
        property.countType = readType(lines, "the list's count type");
        if (!isPlyIntegerType(property.countType)) lines.fail("a list's count type must be an integer type");
        property.type = readType(lines, "the list's item type");
      } else {
        if (kind.empty()) lines.fail("expected the property's type, found the end of the line");
        property.type = typeOrFail(lines, kind);
      }
      property.name = std::string(lines.token());
      if (property.name.empty()) lines.fail("expected the property's name, found the end of the line");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      lines.fail(
          fmt::format("{} is not a PLY header line (format, element, property, comment, obj_info, "
                      "end_header)",
                      quoteTokenForMessage(keyword)));
    }
  }
  if (!formatSeen) throw InputError(SourceLocation{name, 2}, "the PLY header has no format line");
  return header;
}

}  // namespace lancer
