#include "support/test_images.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "lancer/image/image_io.hpp"

namespace lancer::test {

SampleError sampleError(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  SampleError e;
  if (a.size() != b.size() || a.empty()) return {1e9, 255};
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d = std::abs(int{a[i]} - int{b[i]});
    sum += d;
    e.max = std::max(e.max, d);
  }
  e.mean = sum / static_cast<double>(a.size());
  return e;
}

Image shadedSphere(int width, int height, float phase) {
  Image image(width, height);
  const float cx = width * (0.3f + 0.4f * phase), cy = height * 0.5f, radius = height * 0.35f;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float dx = (x + 0.5f - cx) / radius, dy = (y + 0.5f - cy) / radius;
      const float r2 = dx * dx + dy * dy;
      if (r2 < 1) {
        const float nz = std::sqrt(1 - r2);
        const float diffuse = std::max(0.0f, -0.4f * dx - 0.5f * dy + 0.77f * nz);
        image.at(x, y) = {0.1f + 0.8f * diffuse, 0.08f + 0.5f * diffuse, 0.05f + 0.3f * diffuse, 1};
      } else {
        const float t = static_cast<float>(y) / static_cast<float>(height);
        image.at(x, y) = {0.2f * t, 0.25f * t, 0.5f * t + 0.1f, 1};
      }
    }
  }
  return image;
}

Image noise(int width, int height) {
  Image image(width, height);
  std::uint32_t state = 12345;
  for (Rgba& p : image.pixels()) {
    auto next = [&] {
      state = state * 1664525u + 1013904223u;
      return static_cast<float>(state >> 24) / 255.0f;
    };
    p = {next(), next(), next(), 1};
  }
  return image;
}

std::vector<std::uint8_t> pngRgb8(const std::string& path) {
  return encodeImage8(readPng(path), TransferCurve::Linear, 3);
}

int differingPixels(const Image& a, const Image& b) {
  int count = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Rgba p = a.at(x, y), q = b.at(x, y);
      count += !(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a);
    }
  }
  return count;
}

void appendLittleEndian(std::string& bytes, std::uint64_t value, int size) {
  for (int i = 0; i < size; ++i) bytes += static_cast<char>((value >> (8 * i)) & 0xff);
}

namespace {

void exrAttribute(std::string& bytes, const std::string& name, const std::string& type,
                  const std::string& value) {
  bytes += name + '\0' + type + '\0';
  appendLittleEndian(bytes, value.size(), 4);
  bytes += value;
}

}  // namespace

// OpenEXR file layout: magic, version 2, the required attributes, an empty name, the offset table.
std::string exrFile(int width, int height, int compression, int chunks,
                    const std::function<std::uint64_t(int, std::uint64_t)>& offsetOf, const std::string& tail,
                    const std::vector<std::string>& channelNames) {
  std::string bytes = "\x76\x2f\x31\x01";
  appendLittleEndian(bytes, 2, 4);
  std::string channels;
  for (const std::string& name : channelNames) {
    channels += name + '\0';
    appendLittleEndian(channels, 1, 4);  // HALF
    appendLittleEndian(channels, 0, 4);  // pLinear and reserved
    appendLittleEndian(channels, 1, 4);  // xSampling
    appendLittleEndian(channels, 1, 4);  // ySampling
  }
  channels += '\0';
  std::string box, one, zeros;
  for (int value : {0, 0, width - 1, height - 1})
    appendLittleEndian(box, static_cast<std::uint32_t>(value), 4);
  appendLittleEndian(one, 0x3f800000, 4);  // 1.0f
  appendLittleEndian(zeros, 0, 8);
  exrAttribute(bytes, "channels", "chlist", channels);
  exrAttribute(bytes, "compression", "compression", std::string(1, static_cast<char>(compression)));
  exrAttribute(bytes, "dataWindow", "box2i", box);
  exrAttribute(bytes, "displayWindow", "box2i", box);
  exrAttribute(bytes, "lineOrder", "lineOrder", std::string(1, '\0'));
  exrAttribute(bytes, "pixelAspectRatio", "float", one);
  exrAttribute(bytes, "screenWindowCenter", "v2f", zeros);
  exrAttribute(bytes, "screenWindowWidth", "float", one);
  bytes += '\0';
  const std::uint64_t chunksStart = bytes.size() + 8 * static_cast<std::uint64_t>(chunks);
  for (int i = 0; i < chunks; ++i) appendLittleEndian(bytes, offsetOf(i, chunksStart), 8);
  return bytes + tail;
}

}  // namespace lancer::test
