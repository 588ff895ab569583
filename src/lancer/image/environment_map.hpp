// Equirectangular environment maps from either format users have: Radiance .hdr (hdr_reader.hpp) or
// OpenEXR (exr_io.hpp), told apart by the file's first bytes, so the name's extension does not matter.
#pragma once

#include <string>

#include "lancer/image/hdr_reader.hpp"

namespace lancer {

// The map's linear RGB radiance, row 0 at the top. Throws InputError naming the file and what was
// read: missing, a folder or unreadable, neither format (an image of another format named as such),
// an EXR with a non-finite value (negative values, a filter's ringing, are read as 0), a size the file
// or the memory budget cannot hold. The 2:1 shape is the caller's check.
HdrImage readEnvironmentMap(const std::string& path);

}  // namespace lancer
