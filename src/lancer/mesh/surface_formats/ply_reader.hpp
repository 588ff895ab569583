// PLY surfaces (ascii, binary_little_endian, binary_big_endian) read into a Mesh of one group: the
// vertex element's x, y, z as points and each of its other scalar properties (a temperature, a
// scanner's quality, nx, red, ...) as a node field named after it; the face element's vertex_indices
// (or vertex_index) lists, of any integer types, as faces: triangles and quads as they are, larger
// polygons split into fans. Other elements and list properties are read past. Bad input throws
// InputError at the header's line, the ASCII data's line or the binary data's byte offset.
#pragma once

#include <span>
#include <string>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

Mesh readPly(std::span<const char> bytes, const std::string& name);

}  // namespace lancer
