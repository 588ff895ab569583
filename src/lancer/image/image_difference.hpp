// How far one render is from another, as the benchmarks and tests measure convergence: the
// denoiser against the clean render, the path tracer against a high-sample or Cycles reference.
#pragma once

#include "lancer/image/image.hpp"

namespace lancer {

// The root mean square difference of the linear RGB values (alpha ignored), averaged over the three
// channels of every pixel: the usual RMSE of rendering papers, on radiance rather than on 8-bit
// codes. Throws std::invalid_argument when the sizes differ or the images are empty.
double rootMeanSquareDifference(const Image& a, const Image& b);

}  // namespace lancer
