// OpenEXR output and input (libopenexr): linear radiance as 32-bit float R, G, B, A, with optional
// layers of what the first surface is (albedo, normal, depth), as compositors and denoisers expect
// them. Written atomically, like every lancer output (atomic_file.hpp).
#pragma once

#include <string>
#include <vector>

#include "lancer/image/image.hpp"
#include "lancer/image/image_metadata.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// True when this lancer was built with OpenEXR; without it the functions below throw InputError.
bool exrSupported();

// Extra layers, each empty or of the image's pixel count, rows top to bottom. Channel names:
// albedo.R, albedo.G, albedo.B; normal.X, normal.Y, normal.Z; Z (depth, +infinity where nothing was hit).
struct ExrLayers {
  std::vector<Vec3> albedo;
  std::vector<Vec3> normal;
  std::vector<float> depth;
};

// R, G, B, A as 32-bit floats (no clamping, no curve), ZIP-compressed, plus the non-empty layers; the
// metadata as header attributes ("comments": the command, "software", "xDensity": the DPI).
// Throws InputError naming the file on I/O failure or a build without OpenEXR.
void writeExr(const std::string& path, const Image& image, const ExrLayers& layers = {},
              const ImageMetadata& metadata = {});

// Reads R, G, B (and A, else 1) of any scan-line or tiled EXR, or luminance Y alone as grey, and the
// layers above when present. Throws InputError naming the file for unreadable or non-EXR files, files
// without R, G, B or Y, and sizes the file's chunks or the memory budget (--max-memory) cannot hold,
// before the pixels are allocated.
Image readExr(const std::string& path, ExrLayers* layers = nullptr);

}  // namespace lancer
