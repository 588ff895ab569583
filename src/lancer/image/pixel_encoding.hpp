// Turning linear float intensities into 8-bit file values and back: the linear mapping
// round(255 * clamp(I, 0, 1)) by default, or the sRGB transfer curve (IEC 61966-2-1) as an option.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/image/image.hpp"

namespace lancer {

enum class TransferCurve {
  Linear,  // value = round(255 * clamp(I, 0, 1)), the default
  Srgb,    // value = round(255 * srgb(clamp(I, 0, 1))): brighter mid-tones, what monitors expect
};

// IEC 61966-2-1 piecewise curve, on [0, 1].
float srgbFromLinear(float linear);
float linearFromSrgb(float encoded);

// NaN encodes as 0, +inf as 255. Alpha is always encoded with the Linear curve.
std::uint8_t encode8(float value, TransferCurve curve = TransferCurve::Linear);
float decode8(std::uint8_t value, TransferCurve curve = TransferCurve::Linear);

// 16 bits: round(65535 * curve(clamp(I, 0, 1))).
std::uint16_t encode16(float value, TransferCurve curve = TransferCurve::Linear);
float decode16(std::uint16_t value, TransferCurve curve = TransferCurve::Linear);

// One row as interleaved 8-bit samples: channels is 3 (RGB) or 4 (RGBA); out holds width * channels.
void encodeRow8(std::span<const Rgba> row, TransferCurve curve, int channels, std::uint8_t* out);
// The whole image, rows top to bottom, no padding.
std::vector<std::uint8_t> encodeImage8(const Image& image, TransferCurve curve, int channels);
// The same with 16-bit samples, each two bytes big-endian (PNG's order): out holds width * channels * 2.
void encodeRow16(std::span<const Rgba> row, TransferCurve curve, int channels, std::uint8_t* out);
std::vector<std::uint8_t> encodeImage16(const Image& image, TransferCurve curve, int channels);

}  // namespace lancer
