// Reads gmsh .msh files (MSH 2.2, 4.0 and 4.1; ASCII and binary) into a Mesh: surface elements as
// faces, volume elements as their skin. Bad input throws InputError pointing into the file.
// The reader's parts are in mesh/msh/, reader.cpp first (the sections in file order).
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "lancer/mesh/mesh.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Memory-maps and reads the file; source.loadSeconds holds the time it took. The parse is serial;
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

// The same from bytes in memory (tests, fuzzing); nameForErrors is the file name errors show.
Mesh readMshFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads = 0);

}  // namespace lancer
