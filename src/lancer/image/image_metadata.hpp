// What a picture file says about itself beside its pixels: its print resolution (DPI) and how it was
// made (lancer's version, the command line or Python call), and the checks of the options that set them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lancer/util/input_error.hpp"

namespace lancer {

// Every field is optional: a default ImageMetadata writes nothing beyond the pixels.
struct ImageMetadata {
  double dpi = 0;        // dots per inch, > 0; 0: no resolution in the file
  std::string software;  // e.g. "lancer 0.1.0" (softwareName())
  std::string command;   // how the picture was made: the command line, or the Python call
  bool empty() const { return dpi == 0 && software.empty() && command.empty(); }
};

// "lancer VERSION", CMake's project(VERSION).
std::string softwareName();

// The command line as a shell would take it back: words with spaces or quotes are single-quoted.
std::string quoteCommandLine(int argc, const char* const* argv);

// The highest DPI every format can hold (a JPEG stores it in 16 bits).
inline constexpr double kMaxDpi = 65535;
// The JPEG and WebP quality: 1 (smallest) to 100 (best); 90 unless asked.
inline constexpr int kDefaultImageQuality = 90;

// The one check of a DPI and of a quality, whichever front end (command line, scene file, Python)
// read them; `where` says how the user spelled the option. Throw InputError.
void requireDpi(double dpi, const SourceLocation& where);
void requireImageQuality(long long quality, const SourceLocation& where);

// Pixels per metre for PNG's pHYs chunk: round(dpi / 0.0254).
std::uint32_t pixelsPerMetre(double dpi);

// A little-endian TIFF/EXIF block ("II*\0" and IFD0, as WebP's EXIF chunk holds it, without JPEG's
// "Exif\0\0" prefix) with ImageDescription (the command), XResolution, YResolution and
// ResolutionUnit (inch) when a DPI is set, and Software. Empty when `metadata` is.
std::vector<std::uint8_t> exifBlock(const ImageMetadata& metadata);

}  // namespace lancer
