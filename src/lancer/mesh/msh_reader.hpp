// gmsh's mesh and view files (callers open meshes through mesh_file.hpp, which also reads STL, OBJ
// and PLY): gmsh .msh files (MSH 2.2, 4.0 and 4.1; ASCII and binary) and
// list-based .pos views (GetDP's default output) read into a Mesh, surface elements as faces, volume
// elements as their skin; .pos views put on a mesh read from elsewhere. Bad input throws InputError
// pointing into the file. The .msh reader's parts are in mesh/msh/, reader.cpp first (the sections
// in file order); the .pos reader's in mesh/pos/.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Memory-maps and reads the file; a list-based .pos view (recognised by content, or by its .pos name
// when it looks like neither) becomes the mesh of its elements with its views' steps as element-node
// fields (mesh/pos/pos_mesh.hpp). source.loadSeconds holds the time it took. The parse is serial;
// the mesh assembly after it runs on `threads` threads (0: every core), the same mesh for any count.
// When the file's result steps ($NodeData, $ElementData) would take more than residentFieldBytes as
// floats, they are left in the file and read back when needed (MeshField::stored); the default is
// defaultResidentFieldBytes().
Mesh readMsh(const std::string& path, int threads = 0);
Mesh readMsh(const std::string& path, int threads, std::uint64_t residentFieldBytes);

// How much memory result steps may take before they are left in their file: 64 MB, or
// LANCER_STEP_MEMORY_MB megabytes. Throws InputError when that variable is not a number.
inline constexpr std::uint64_t kDefaultResidentFieldBytes = std::uint64_t{64} << 20;
std::uint64_t defaultResidentFieldBytes();

// The mesh and its volume elements with the fields inside them (mesh/volume/volume_mesh.hpp), for
// slices, isosurfaces, field lines and probes. The volume is empty when the file has no volume
// elements; a list-based .pos view gives the volume elements of its views, each view with volume
// elements an element-node field on them (meshFromPos, mesh/pos/pos_mesh.hpp). Every step is kept
// in memory.
struct MeshWithVolume {
  Mesh mesh;
  std::shared_ptr<const VolumeMesh> volume;
};
MeshWithVolume readMshWithVolume(const std::string& path, int threads = 0);

// The same from bytes in memory (tests, fuzzing); nameForErrors is the file name errors show.
Mesh readMshFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads = 0);

// Whether readMsh takes the file for a view file (a .pos) rather than a mesh: what the command line
// asks of its inputs to tell the mesh from the views to put on it. False for a file it cannot read.
bool isViewFile(const std::string& path);

// Reads list-based .pos files and puts their views on `mesh` (read from another file), each step an
// element-node field, by matching element coordinates (mesh/pos/pos_on_mesh.hpp). The time it takes
// is added to mesh.source.loadSeconds.
void addViewFiles(Mesh& mesh, const std::vector<std::string>& paths);
// The same on a mesh and its volume: each view with volume elements also becomes a field of the
// volume, on the cells whose corners are its elements' (mesh/pos/pos_on_volume.hpp).
void addViewFiles(MeshWithVolume& read, const std::vector<std::string>& paths);

}  // namespace lancer
