// An edge-aware denoiser for rendered radiance, guided by the first surface's albedo, normal and depth
// (feature_buffers.hpp): the edge-avoiding à-trous wavelet filter of Dammertz, Sewtz, Hanika and
// Lensch, "Edge-Avoiding À-Trous Wavelet Transform for fast Global Illumination Filtering" (HPG 2010),
// with the normal and depth edge-stopping functions of Schied et al., SVGF (HPG 2017, section 4.4).
//
// The radiance is divided by the albedo first (demodulated, so texture and element colours are not
// blurred) and multiplied back after. Each of the passes blurs with the 5x5 B3-spline kernel at a
// spacing of 2^pass pixels, every tap weighted down when its normal, depth, albedo or colour differs
// from the centre's (at the centre's albedo): colour differences are measured against the image's noise
// level, estimated robustly (median absolute deviation of the finest wavelet detail, Donoho and
// Johnstone 1994), so a shadow edge far above the noise stays sharp and a clean image barely changes.
// Where the features carry each pixel's own variance (the path tracer's samples) and it exceeds that
// level, the pixel's colour differences are measured against its own deviation instead (as SVGF's
// luminance weight, section 4.3): a firefly, a colour edge far above the picture's noise but not
// above its own samples' spread, takes its neighbours in instead of staying.
#pragma once

#include "lancer/image/image.hpp"
#include "lancer/render/feature_buffers.hpp"

namespace lancer {

struct DenoiseOptions {
  int passes = 5;             // à-trous levels: a footprint of 4 * 2^passes + 1 pixels
  float normalPower = 128;    // SVGF's sigma_n: weight max(0, n_p . n_q)^normalPower
  float depthSigma = 1;       // SVGF's sigma_z, against the depth gradient times the tap's offset
  float albedoSigma = 0.05f;  // weight exp(-|a_p - a_q|^2 / albedoSigma^2)
  float colorSigma = 3;       // in units of the estimated noise; halved each pass (Dammertz)
  int threads = 0;            // rows in parallel (0: all cores); the result is the same for any count
};

// The filtered image (alpha copied); `features` must have the image's size. Deterministic.
Image denoise(const Image& noisy, const FeatureBuffers& features, const DenoiseOptions& options = {});

// The noise level of `image` where the features are smooth, as denoise estimates it (for tests).
float estimateNoise(const Image& image, const FeatureBuffers& features);

}  // namespace lancer
