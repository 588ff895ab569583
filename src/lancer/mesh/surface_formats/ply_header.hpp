// The header of a PLY file (Greg Turk's polygon file format, 1994; the types rply and Blender
// write): its format, and its elements with their properties, read and checked before any data.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lancer {

enum class PlyType : std::uint8_t { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
int plyTypeBytes(PlyType type);
bool isPlyIntegerType(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;  // of the value, or of a list's items
  bool list = false;
  PlyType countType = PlyType::kUint8;  // of a list's length
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::int64_t line = 0;  // where the header declares it
  // Bytes of one entry in a binary file: exact when it has no list, the least it can take otherwise
  // (each list empty); in an ASCII file, the least its text can take (a digit and a blank a value).
  std::uint64_t minimumBinaryBytes() const;
  std::uint64_t minimumTextBytes() const { return 2 * properties.size(); }
  // The index of the property called `name`, -1 when there is none.
  int find(std::string_view name) const;
};

struct PlyHeader {
  enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
  Format format = Format::kAscii;
  std::vector<PlyElement> elements;
  std::size_t dataOffset = 0;  // the first byte after end_header's line
  std::int64_t dataLine = 0;   // its line, for ASCII data
};

// True when the bytes start with PLY's magic line.
bool looksLikePly(std::span<const char> head);

// Throws InputError at the header's line for what lancer cannot read: a header with no end_header,
// an unknown format or property type, a property outside an element, a count that is no number.
PlyHeader readPlyHeader(std::span<const char> bytes, const std::string& name);

}  // namespace lancer
