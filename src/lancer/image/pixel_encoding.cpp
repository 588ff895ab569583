#include "lancer/image/pixel_encoding.hpp"

#include <cmath>

namespace lancer {

float srgbFromLinear(float linear) {
  const double v = linear;
  return static_cast<float>(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

float linearFromSrgb(float encoded) {
  const double v = encoded;
  return static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

std::uint8_t encode8(float value, TransferCurve curve) {
  if (!(value > 0.0f)) return 0;  // also NaN
  if (value >= 1.0f) return 255;
  const double v = curve == TransferCurve::Srgb ? srgbFromLinear(value) : value;
  return static_cast<std::uint8_t>(std::lround(255.0 * v));
}

float decode8(std::uint8_t value, TransferCurve curve) {
  const float v = static_cast<float>(value) / 255.0f;
  return curve == TransferCurve::Srgb ? linearFromSrgb(v) : v;
}

std::uint16_t encode16(float value, TransferCurve curve) {
  if (!(value > 0.0f)) return 0;  // also NaN
  if (value >= 1.0f) return 65535;
  const double v = curve == TransferCurve::Srgb ? srgbFromLinear(value) : value;
  return static_cast<std::uint16_t>(std::lround(65535.0 * v));
}

float decode16(std::uint16_t value, TransferCurve curve) {
  const float v = static_cast<float>(value) / 65535.0f;
  return curve == TransferCurve::Srgb ? linearFromSrgb(v) : v;
}

void encodeRow16(std::span<const Rgba> row, TransferCurve curve, int channels, std::uint8_t* out) {
  const auto put = [&out](std::uint16_t v) {
    *out++ = static_cast<std::uint8_t>(v >> 8);
    *out++ = static_cast<std::uint8_t>(v & 0xff);
  };
  for (const Rgba& p : row) {
    put(encode16(p.r, curve));
    put(encode16(p.g, curve));
    put(encode16(p.b, curve));
    if (channels == 4) put(encode16(p.a));
  }
}

std::vector<std::uint8_t> encodeImage16(const Image& image, TransferCurve curve, int channels) {
  const std::size_t rowSize =
      static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(channels) * 2;
  std::vector<std::uint8_t> out(rowSize * static_cast<std::size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y)
    encodeRow16(image.row(y), curve, channels, out.data() + rowSize * static_cast<std::size_t>(y));
  return out;
}

void encodeRow8(std::span<const Rgba> row, TransferCurve curve, int channels, std::uint8_t* out) {
  for (const Rgba& p : row) {
    *out++ = encode8(p.r, curve);
    *out++ = encode8(p.g, curve);
    *out++ = encode8(p.b, curve);
    if (channels == 4) *out++ = encode8(p.a);
  }
}

std::vector<std::uint8_t> encodeImage8(const Image& image, TransferCurve curve, int channels) {
  const std::size_t rowSize = static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(channels);
  std::vector<std::uint8_t> out(rowSize * static_cast<std::size_t>(image.height()));
  for (int y = 0; y < image.height(); ++y) {
    encodeRow8(image.row(y), curve, channels, out.data() + rowSize * static_cast<std::size_t>(y));
  }
  return out;
}

}  // namespace lancer
