// Mapping 8-bit RGB pixels to palette indices, plainly or with dithering, which trades banding in
// smooth shading for fine noise.
#pragma once

#include <cstdint>
#include <span>

#include "lancer/image/palette_quantizer.hpp"

namespace lancer {

enum class Dither {
  None,            // nearest palette colour
  Ordered,         // 8x8 Bayer threshold matrix: stable between frames, so no crawling on animations
  FloydSteinberg,  // error diffusion (Floyd & Steinberg 1976), serpentine scan: least visible noise
};

// rgb: width * height interleaved RGB; indices: width * height palette indices.
void mapToPalette(std::span<const std::uint8_t> rgb, int width, int height, NearestColour& nearest,
                  Dither dither, std::span<std::uint8_t> indices);

}  // namespace lancer
