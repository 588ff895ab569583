// Golden-image comparison for every module's tests: compare a rendered Image with a stored PNG by
// PSNR over 8-bit values; on failure leave actual, expected and difference PNGs to look at.
#pragma once

#include <string>

#include "lancer/image/image.hpp"
#include "lancer/image/pixel_encoding.hpp"

namespace lancer::test {

// The PSNR floor of the render goldens: differences of about one 8-bit step everywhere stay far
// above it; a shifted shadow, a wrong normal, a missing or moved cap or a face in another colour
// falls far below (the shading, cut and multi-material goldens each have a test that checks this).
inline constexpr double kRenderGoldenMinPsnrDb = 40.0;

// PSNR in dB over the 8-bit encoded R, G, B (and alpha when either image has transparency):
// 10 log10(255^2 / MSE); +infinity for identical images. Sizes must match.
double psnr8(const Image& a, const Image& b, TransferCurve curve = TransferCurve::Linear);

// True when LANCER_UPDATE_GOLDEN=1 is set: expectImageNear then (re)writes the expected file.
bool updatingGoldenFiles();

// Adds a gtest failure unless `actual`, encoded with `curve`, has a PSNR of at least minPsnrDb
// against the PNG at expectedPngPath. The failure message gives the PSNR and the paths of
// actual.png, expected.png and difference.png (|actual - expected| x 8 per channel), written to
//   $LANCER_GOLDEN_FAILURE_DIR, else ./golden-failures (the test's working folder: the build tree
//   under ctest), else /tmp/lancer-golden-failures; one sub-folder per test.
// With LANCER_UPDATE_GOLDEN=1 it writes `actual` to expectedPngPath instead and passes.
void expectImageNear(const Image& actual, const std::string& expectedPngPath, double minPsnrDb,
                     TransferCurve curve = TransferCurve::Linear);

}  // namespace lancer::test
