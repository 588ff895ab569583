#include "lancer/render/progress_line.hpp"

#include <cstdio>

namespace lancer {

void printProgressLine(const RenderProgress& progress) {
  const double raysPerSecond = progress.seconds > 0 ? progress.rays / progress.seconds : 0;
  const double eta =
      progress.fraction > 0 ? progress.seconds * (1 - progress.fraction) / progress.fraction : 0;
  std::fprintf(stderr, "\r  %5.1f%%  %7.2f Mrays/s  ETA %5.1f s ", 100 * progress.fraction,
               raysPerSecond * 1e-6, eta);
  std::fflush(stderr);
}

}  // namespace lancer
