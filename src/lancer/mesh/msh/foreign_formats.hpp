// Files people give lancer that are not gmsh meshes (a .geo script, STL, STEP, IGES, BREP, VTK,
// OBJ; a .pos view is read, mesh/pos/): recognised by content, then by extension, and answered with the gmsh
// command that makes a .msh of them, instead of a parser error.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace lancer {

// "this is an STL surface (binary), not a gmsh mesh: make one with 'gmsh part.stl -save -o part.msh'";
// "" when the file looks like none of these formats. head: the file's first bytes (4 KiB is plenty),
// fileBytes: its whole size (binary STL is recognised by it), path: the name the user gave.
std::string foreignFileMessage(std::span<const char> head, std::uint64_t fileBytes, const std::string& path);

// True when the bytes start like a gmsh .msh file ($MeshFormat, or MSH 1's $NOD).
bool looksLikeMsh(std::span<const char> head);

}  // namespace lancer
