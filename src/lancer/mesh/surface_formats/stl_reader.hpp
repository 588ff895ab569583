// STL surfaces (ASCII and binary) read into a Mesh: each ASCII `solid` is a physical surface named
// after it, a binary file one unnamed group (gmsh writes a block a physical surface: then a group a
// block, named after its header); the points STL repeats for every facet are welded so
// that normals are smooth across facets and shells are found. Bad input throws InputError.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Binary when the size is what its 84-byte header's triangle count says (84 + 50 per triangle), even
// when the header starts with "solid" as some exporters write it; ASCII when it starts with "solid"
// and reads as text. head: the first bytes (4 KiB is plenty), fileBytes: the whole size.
enum class StlKind { kNone, kAscii, kBinary };
StlKind stlKindOf(std::span<const char> head, std::uint64_t fileBytes);

// kind: what stlKindOf said, or kBinary for a .stl file that is neither (then the size check says what
// is wrong with it).
Mesh readStl(std::span<const char> bytes, const std::string& name, StlKind kind);

}  // namespace lancer
