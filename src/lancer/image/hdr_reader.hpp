// Radiance RGBE (.hdr) images (Greg Ward, "Real Pixels", Graphics Gems II, 1991; the format of
// Radiance's ra_* tools): the header, then flat or run-length-encoded scanlines of shared-exponent
// RGB. For environment maps; errors name the file and what was read.
#pragma once

#include <string>
#include <vector>

#include "lancer/math/vec3.hpp"

namespace lancer {

struct HdrImage {
  int width = 0, height = 0;
  std::vector<Vec3> pixels;  // row 0 at the top, linear radiance
};

// Throws InputError (file and what was wrong) for a missing, unreadable or malformed file.
HdrImage readRadianceHdr(const std::string& path);
// The same from the file's bytes; `path` for messages.
HdrImage decodeRadianceHdr(const std::string& bytes, const std::string& path);

}  // namespace lancer
