// Files people give lancer that it does not read (a .geo script, STEP, IGES, BREP, VTK, VTU, OFF, UNV,
// Abaqus .inp, ANSYS Fluent .msh; .pos views, STL, OBJ and PLY are read: mesh_file.hpp): recognised by
// content, then by extension, and answered with the gmsh or meshio command that makes a .msh of them
// (each checked with Debian 12's gmsh 4.8.4 and python3-meshio 7.0.0), instead of a parser error.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace lancer {

// "this is an I-deas universal file (UNV), not a gmsh mesh: convert it with 'gmsh part.unv -save -o
// part.msh'"; "" when the file looks like none of these formats. head: the file's first bytes (4 KiB
// is plenty), path: the name the user gave.
std::string foreignFileMessage(std::span<const char> head, const std::string& path);

// True when the bytes start like a gmsh .msh file ($MeshFormat, or MSH 1's $NOD).
bool looksLikeMsh(std::span<const char> head);

}  // namespace lancer
