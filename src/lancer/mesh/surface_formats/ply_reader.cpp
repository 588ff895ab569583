#include "lancer/mesh/surface_formats/ply_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "lancer/mesh/msh/text_number.hpp"
#include "lancer/mesh/surface_formats/ply_header.hpp"
#include "lancer/mesh/surface_formats/surface_mesh.hpp"
#include "lancer/mesh/surface_formats/text_lines.hpp"
#include "lancer/util/memory_budget.hpp"

namespace lancer {
namespace {

// What a vertex and a face take while read and assembled (the point, its values, the assembler's
// node and face arrays), for the memory budget.
constexpr std::uint64_t kVertexMemoryBytes = 96;
constexpr std::uint64_t kFaceMemoryBytes = 96;

// Entries of an ASCII file: one a line, values as text.
class AsciiValues {
 public:
  AsciiValues(std::span<const char> bytes, const std::string& name, const PlyHeader& header)
      : lines_(bytes, name, header.dataOffset, header.dataLine), bytes_(bytes) {}

  void requireEntries(const PlyElement& element) {
    check(element, element.minimumTextBytes(),
          bytes_.size() - std::min(bytes_.size(), lines_.nextLineOffset()));
  }
  void beginEntry(const PlyElement& element, std::uint64_t index) {
    do {
      if (!lines_.nextLine())
        lines_.failAtEnd(
            fmt::format("the file ends after {} of the {} {} entries the header declares (it looks "
                        "truncated)",
                        index, element.count, element.name));
    } while (lines_.atLineEnd());
  }
  void endEntry(const PlyElement& element) {
    if (!lines_.atLineEnd())
      lines_.fail(fmt::format("{} after the values of a {} entry: the header declares {} properties",
                              quoteTokenForMessage(lines_.token()), element.name, element.properties.size()));
  }
  double value(PlyType type, const char* what) {
    if (!isPlyIntegerType(type)) return lines_.readNumber(what);
    return static_cast<double>(lines_.readInteger(what));
  }
  std::int64_t integer(PlyType, const char* what) { return lines_.readInteger(what); }
  [[noreturn]] void fail(const std::string& message) const { lines_.fail(message); }

 private:
  void check(const PlyElement& element, std::uint64_t entryBytes, std::uint64_t remaining) const {
    if (entryBytes != 0 && element.count > remaining / entryBytes)
      throw InputError(
          SourceLocation{lines_.name(), element.line},
          fmt::format("element {} declares {} entries of at least {} bytes each, but only {} bytes "
                      "remain in the file (truncated file or a corrupt count)",
                      element.name, element.count, entryBytes, remaining));
  }

  TextLines lines_;
  std::span<const char> bytes_;
};

// Entries of a binary file, values in the header's byte order.
class BinaryValues {
 public:
  BinaryValues(std::span<const char> bytes, const std::string& name, const PlyHeader& header)
      : bytes_(bytes),
        name_(name),
        pos_(header.dataOffset),
        swap_(header.format == PlyHeader::Format::kBinaryBigEndian) {}

  void requireEntries(const PlyElement& element) const {
    const std::uint64_t entryBytes = element.minimumBinaryBytes();
    const std::uint64_t remaining = bytes_.size() - pos_;
    if (entryBytes != 0 && element.count > remaining / entryBytes)
      throw InputError(
          SourceLocation{name_, 0, 0, static_cast<std::int64_t>(pos_)},
          fmt::format("element {} (header line {}) declares {} entries of at least {} bytes each, but "
                      "only {} bytes remain in the file (truncated file or a corrupt count)",
                      element.name, element.line, element.count, entryBytes, remaining));
  }
  void beginEntry(const PlyElement& element, std::uint64_t index) {
    element_ = &element;
    entry_ = index;
  }
  void endEntry(const PlyElement&) {}
  double value(PlyType type, const char*) {
    valueAt_ = pos_;
    const int size = plyTypeBytes(type);
    if (bytes_.size() - pos_ < static_cast<std::size_t>(size))
      fail(fmt::format("the file ends inside {} entry {} of {} (it looks truncated)", element_->name,
                       entry_ + 1, element_->count));
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, static_cast<std::size_t>(size));
    pos_ += static_cast<std::size_t>(size);
    if (swap_ == (std::endian::native == std::endian::little))
      for (int i = 0; i < size / 2; ++i) std::swap(raw[i], raw[size - 1 - i]);
    return decode(type, raw);
  }
  std::int64_t integer(PlyType type, const char* what) {
    return static_cast<std::int64_t>(value(type, what));
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(SourceLocation{name_, 0, 0, static_cast<std::int64_t>(valueAt_)}, message);
  }

 private:
  static double decode(PlyType type, const unsigned char* raw) {
    switch (type) {
      case PlyType::kInt8:
        return static_cast<std::int8_t>(raw[0]);
      case PlyType::kUint8:
        return raw[0];
      case PlyType::kInt16:
        return load<std::int16_t>(raw);
      case PlyType::kUint16:
        return load<std::uint16_t>(raw);
      case PlyType::kInt32:
        return load<std::int32_t>(raw);
      case PlyType::kUint32:
        return load<std::uint32_t>(raw);
      case PlyType::kFloat32:
        return load<float>(raw);
      case PlyType::kFloat64:
        break;
    }
    return load<double>(raw);
  }
  template <typename T>
  static double load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof value);
    return static_cast<double>(value);
  }

  std::span<const char> bytes_;
  const std::string& name_;
  std::size_t pos_;
  std::size_t valueAt_ = 0;
  bool swap_;
  const PlyElement* element_ = nullptr;
  std::uint64_t entry_ = 0;
};

// The vertex element's use of its properties: which are x, y, z, which become fields.
struct VertexLayout {
  int coordinate[3] = {-1, -1, -1};
  std::vector<int> fieldOf;  // per property: the field it fills, -1 for none
};

template <typename Values>
void readVertices(Values& values, const PlyElement& element, const VertexLayout& layout, SurfaceData& data) {
  static const char* const kWhat[] = {"a vertex's x", "a vertex's y", "a vertex's z"};
  data.points.reserve(element.count);
  for (SurfaceVertexField& field : data.fields) field.values.reserve(element.count);
  for (std::uint64_t i = 0; i < element.count; ++i) {
    values.beginEntry(element, i);
    double xyz[3] = {0, 0, 0};
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (property.list) {
        const std::int64_t length = values.integer(property.countType, "a list's length");
        if (length < 0) values.fail(fmt::format("list {} has a negative length ({})", property.name, length));
        for (std::int64_t k = 0; k < length; ++k) values.value(property.type, "a list's item");
        continue;
      }
      const int axis = p == static_cast<std::size_t>(layout.coordinate[0])   ? 0
                       : p == static_cast<std::size_t>(layout.coordinate[1]) ? 1
                       : p == static_cast<std::size_t>(layout.coordinate[2]) ? 2
                                                                             : -1;
      const double v = values.value(property.type, axis >= 0 ? kWhat[axis] : "a vertex property");
      if (!std::isfinite(v))
        values.fail(fmt::format("vertex {} has a non-finite {} ({})", i, property.name, v));
      if (axis >= 0) xyz[axis] = v;
      if (layout.fieldOf[p] >= 0)
        data.fields[static_cast<std::size_t>(layout.fieldOf[p])].values.push_back(v);
    }
    values.endEntry(element);
    data.points.push_back(Vec3d{xyz[0], xyz[1], xyz[2]});
  }
}

template <typename Values>
std::uint64_t readFaces(Values& values, const PlyElement& element, int indices, std::uint64_t vertexCount,
                        SurfaceGroup& group) {
  std::vector<std::uint32_t> corners;
  std::uint64_t skipped = 0;  // faces of fewer than 3 vertices
  for (std::uint64_t i = 0; i < element.count; ++i) {
    values.beginEntry(element, i);
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (!property.list) {
        values.value(property.type, "a face property");
        continue;
      }
      const std::int64_t length = values.integer(property.countType, "a list's length");
      if (length < 0) values.fail(fmt::format("face {} has a list of negative length ({})", i, length));
      if (static_cast<int>(p) != indices) {
        for (std::int64_t k = 0; k < length; ++k) values.value(property.type, "a list's item");
        continue;
      }
      corners.clear();
      for (std::int64_t k = 0; k < length; ++k) {
        const std::int64_t index = values.integer(property.type, "a vertex index");
        if (index < 0 || static_cast<std::uint64_t>(index) >= vertexCount)
          values.fail(fmt::format("face {} uses vertex {}, but the file has {} vertices (numbered from 0)", i,
                                  index, vertexCount));
        corners.push_back(static_cast<std::uint32_t>(index));
      }
    }
    values.endEntry(element);
    if (corners.size() < 3) {
      ++skipped;  // a point or an edge, as meshio writes them among the faces
    } else if (corners.size() == 4) {
      group.quads.insert(group.quads.end(), corners.begin(), corners.end());
    } else {
      for (std::size_t k = 1; k + 1 < corners.size(); ++k)
        for (const std::uint32_t corner : {corners[0], corners[k], corners[k + 1]})
          group.triangles.push_back(corner);
    }
  }
  return skipped;
}

template <typename Values>
void skipEntries(Values& values, const PlyElement& element) {
  for (std::uint64_t i = 0; i < element.count; ++i) {
    values.beginEntry(element, i);
    for (const PlyProperty& property : element.properties) {
      const std::int64_t length = property.list ? values.integer(property.countType, "a list's length") : 1;
      if (length < 0) values.fail(fmt::format("list {} has a negative length ({})", property.name, length));
      for (std::int64_t k = 0; k < length; ++k) values.value(property.type, "a value");
    }
    values.endEntry(element);
  }
}

// Returns the warnings it has for the mesh.
template <typename Values>
std::vector<std::string> readData(Values& values, const PlyHeader& header, const std::string& name,
                                  SurfaceData& data) {
  std::vector<std::string> warnings;
  const PlyElement* vertex = nullptr;
  for (const PlyElement& element : header.elements) {
    values.requireEntries(element);  // each alone first: a corrupt count says so before any other error
    if (element.name == "vertex") vertex = &element;
  }
  if (!vertex) throw InputError(SourceLocation{name}, "the PLY header declares no vertex element");
  VertexLayout layout;
  for (int axis = 0; axis < 3; ++axis) {
    const char axisName[2] = {static_cast<char>('x' + axis), '\0'};
    layout.coordinate[axis] = vertex->find(axisName);
    if (layout.coordinate[axis] < 0 ||
        vertex->properties[static_cast<std::size_t>(layout.coordinate[axis])].list)
      throw InputError(
          SourceLocation{name, vertex->line},
          fmt::format("the vertex element has no scalar property {}: a PLY vertex needs x, y and z",
                      axisName));
  }
  for (std::size_t p = 0; p < vertex->properties.size(); ++p) {
    const PlyProperty& property = vertex->properties[p];
    const bool field = !property.list && static_cast<int>(p) != layout.coordinate[0] &&
                       static_cast<int>(p) != layout.coordinate[1] &&
                       static_cast<int>(p) != layout.coordinate[2];
    layout.fieldOf.push_back(field ? static_cast<int>(data.fields.size()) : -1);
    if (field) data.fields.push_back(SurfaceVertexField{property.name, {}});
  }
  SurfaceGroup& group = data.group("");
  for (const PlyElement& element : header.elements) {
    values.requireEntries(element);
    if (&element == vertex) {
      requireMemory(saturatingProduct(element.count, kVertexMemoryBytes + 8 * data.fields.size()),
                    SourceLocation{name, element.line}, fmt::format("{} vertices", element.count));
      if (element.count > UINT32_MAX - 1)
        throw InputError(SourceLocation{name, element.line},
                         fmt::format("{} vertices: too many for lancer (at most 4294967294)", element.count));
      readVertices(values, element, layout, data);
    } else if (element.name == "face") {
      int indices = element.find("vertex_indices");
      if (indices < 0) indices = element.find("vertex_index");
      if (indices < 0 || !element.properties[static_cast<std::size_t>(indices)].list ||
          !isPlyIntegerType(element.properties[static_cast<std::size_t>(indices)].type))
        throw InputError(SourceLocation{name, element.line},
                         "the face element has no vertex_indices (or vertex_index) list of integers");
      requireMemory(saturatingProduct(element.count, kFaceMemoryBytes), SourceLocation{name, element.line},
                    fmt::format("{} faces", element.count));
      if (const std::uint64_t skipped = readFaces(values, element, indices, vertex->count, group))
        warnings.push_back(formatInputWarning(
            SourceLocation{name, element.line},
            fmt::format("{} of the {} faces have fewer than 3 vertices (points or edges): left out", skipped,
                        element.count)));
    } else {
      skipEntries(values, element);
    }
  }
  return warnings;
}

}  // namespace

Mesh readPly(std::span<const char> bytes, const std::string& name) {
  const PlyHeader header = readPlyHeader(bytes, name);
  SurfaceData data;
  MeshSourceInfo source;
  if (header.format == PlyHeader::Format::kAscii) {
    AsciiValues values(bytes, name, header);
    source.warnings = readData(values, header, name, data);
  } else {
    BinaryValues values(bytes, name, header);
    source.warnings = readData(values, header, name, data);
  }
  source.path = name;
  source.format = "ply";
  source.binary = header.format != PlyHeader::Format::kAscii;
  source.formatVersion = header.format == PlyHeader::Format::kAscii                ? "ascii"
                         : header.format == PlyHeader::Format::kBinaryLittleEndian ? "binary_little_endian"
                                                                                   : "binary_big_endian";
  source.fileBytes = bytes.size();
  return meshFromSurface(data, std::move(source));
}

}  // namespace lancer
