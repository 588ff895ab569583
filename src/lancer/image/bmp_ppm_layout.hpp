// The byte layout of the BMP and PPM files lancer writes, in pieces, so that the whole-image encoders
// (encodeBmp, encodePpm) and the row-by-row writer (ImageRowWriter) produce the same bytes.
// Internal to the image module.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "lancer/image/image.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer {

// BITMAPFILEHEADER + BITMAPINFOHEADER: 24-bit BI_RGB with bottom-up rows. Throws InputError (no
// location; callers add the path) when the file would pass BMP's 4 GiB limit.
std::vector<std::uint8_t> bmpHeader(int width, int height);
// Bytes per stored row: 3 per pixel, padded to a multiple of 4.
std::uint64_t bmpRowBytes(int width);
// One row as BGR with zero padding: bmpRowBytes(row.size()) bytes at `out`.
void encodeBmpRow(std::span<const Rgba> row, TransferCurve curve, std::uint8_t* out);

// Binary P6 with maxval 255; RGB rows follow from the top.
std::string ppmHeader(int width, int height);

}  // namespace lancer
