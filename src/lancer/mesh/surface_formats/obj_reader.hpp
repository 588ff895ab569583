// Wavefront OBJ surfaces read into a Mesh: `v` points and `f` faces (v, v/vt, v//vn and v/vt/vn
// corners, negative indices counting back from the last point), triangles and quads as they are,
// larger polygons split into fans; each `g` or `o` name a physical surface. Texture coordinates,
// normals, materials (mtllib, usemtl), smoothing groups, lines and free-form statements are
// ignored. Bad input throws InputError at file:line:column.
#pragma once

#include <span>
#include <string>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

// Whether the text reads as OBJ: its first statements are OBJ statements, and one is `v` (what the
// mesh door asks of a file with no telling name).
bool looksLikeObj(std::span<const char> head);

Mesh readObj(std::span<const char> bytes, const std::string& name);

}  // namespace lancer
