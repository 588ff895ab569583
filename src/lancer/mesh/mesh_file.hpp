// The one door to mesh files: gmsh .msh and .pos views (msh_reader.hpp), STL, OBJ and PLY surfaces
// (surface_formats/), told apart by their content (by name only where the content cannot tell), and
// any other mesh or CAD format answered with the command that converts it (msh/foreign_formats.hpp).
// Callers open meshes here, never through a reader's internals.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/msh_reader.hpp"

namespace lancer {

// Reads any mesh file lancer reads; threads and residentFieldBytes as readMsh's (a surface file has
// no stored steps). Throws InputError pointing into the file.
Mesh readMeshFile(const std::string& path, int threads = 0);
Mesh readMeshFile(const std::string& path, int threads, std::uint64_t residentFieldBytes);
// With the volume elements (empty for a surface file or a view).
MeshWithVolume readMeshFileWithVolume(const std::string& path, int threads = 0);
// The same from bytes in memory (tests, fuzzing); nameForErrors is the file name errors show, and its
// extension counts as a file's would.
Mesh readMeshFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads = 0);

// Whether a command line's input is a mesh rather than a scene: a .msh by name, or by content a mesh,
// a view, a surface, or a format the reader answers with a conversion command.
bool isMeshFile(const std::string& path);

}  // namespace lancer
