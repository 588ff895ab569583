// Reads gmsh .msh files (MSH 2.2, 4.0 and 4.1; ASCII and binary) into a Mesh: surface elements as
// faces, volume elements as their skin. Bad input throws InputError pointing into the file.
// The reader's parts are in mesh/msh/, reader.cpp first (the sections in file order).
#pragma once

#include <span>
#include <string>

#include "lancer/mesh/mesh.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Memory-maps and reads the file; source.loadSeconds holds the time it took. The parse is serial;
// the mesh assembly after it runs on `threads` threads (0: every core), the same mesh for any count.
Mesh readMsh(const std::string& path, int threads = 0);

// The same from bytes in memory (tests, fuzzing); nameForErrors is the file name errors show.
Mesh readMshFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads = 0);

}  // namespace lancer
