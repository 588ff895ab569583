// Pictures made in code for the image tests (a smooth-shaded sphere, incompressible noise), the
// 8-bit comparisons the writers' tests make against them, and hand-made EXR bytes for the readers'.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lancer/image/image.hpp"

namespace lancer::test {

// Mean and largest absolute difference between 8-bit samples.
struct SampleError {
  double mean = 0;
  int max = 0;
};

// {1e9, 255} when the sizes differ or both are empty.
SampleError sampleError(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b);

// A smooth-shaded test picture: a lit sphere over a vertical gradient, shifted by `phase` (0..1),
// with far more than 256 colours, like a render.
Image shadedSphere(int width, int height, float phase);

// Opaque noise from a fixed linear congruential sequence: it does not compress, so every format's
// file is about 3 bytes per pixel.
Image noise(int width, int height);

// How many pixels of two images of one size differ in any channel (0: the same image, bit for bit).
int differingPixels(const Image& a, const Image& b);

// A PNG as interleaved 8-bit RGB: exactly what lancer stored (linear curve, no alpha).
std::vector<std::uint8_t> pngRgb8(const std::string& path);

// `value`'s low `size` bytes, least significant first, appended to `bytes`.
void appendLittleEndian(std::string& bytes, std::uint64_t value, int size);

// The bytes of a single-part scan-line OpenEXR file of half-float `channels` (in the file's order,
// alphabetical) over width x height, compressed with `compression` (OpenEXR's numbers: 0 none, 3 ZIP,
// 4 PIZ): its header, a table of `chunks` offsets given by offsetOf(i, the byte after the table), then
// `tail`. OpenEXR's writer makes only whole files; a reader's test needs ones that lie, or channels
// lancer's writer does not write.
std::string exrFile(int width, int height, int compression, int chunks,
                    const std::function<std::uint64_t(int, std::uint64_t)>& offsetOf, const std::string& tail,
                    const std::vector<std::string>& channels = {"B", "G", "R"});

}  // namespace lancer::test
