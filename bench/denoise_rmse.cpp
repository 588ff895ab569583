// The denoiser's figures for docs/output.md: renders a scene file, adds seeded Gaussian noise of a few
// deviations to the clean render, denoises each with the clean render's feature buffers, and prints
// the RMSE against the clean render before and after, the denoiser's time, and how much it changes
// the clean render itself.
//   build/bench/denoise_rmse SCENE.toml [THREADS]
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "lancer/image/image_difference.hpp"
#include "lancer/render/denoiser.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/stopwatch.hpp"
#include "support/seeded_noise.hpp"

namespace {

using namespace lancer;

int run(const char* scenePath, int threads) {
  const SceneDescription description = loadScene(scenePath);
  const Scene scene = buildScene(description);
  const Accelerator accelerator =
      Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah);
  const Camera camera = makeCamera(description.camera, scene, description.render);
  const Renderer renderer(scene, accelerator, camera, description.render);
  RenderOptions options;
  options.threads = threads;
  const Image clean = renderer.renderImage(options);
  const Stopwatch featureTime;
  const FeatureBuffers features = renderer.renderFeatures(threads);
  const double featureSeconds = featureTime.seconds();
  DenoiseOptions denoiseOptions;
  denoiseOptions.threads = threads;
  std::printf("%s: %dx%d, %d threads; feature pass %.3f s\n", scenePath, clean.width(), clean.height(),
              threads, featureSeconds);
  std::printf(
      "| noise (deviation) | RMSE noisy | RMSE denoised | ratio | denoise s |\n|---|---|---|---|---|\n");
  for (const float sigma : {0.01f, 0.02f, 0.05f, 0.1f}) {
    const Image noisy = test::withSeededNoise(clean, sigma);
    const Stopwatch time;
    const Image denoised = denoise(noisy, features, denoiseOptions);
    const double seconds = time.seconds();
    const double before = rootMeanSquareDifference(noisy, clean),
                 after = rootMeanSquareDifference(denoised, clean);
    std::printf("| %.2f | %.4f | %.4f | %.2f | %.3f |\n", sigma, before, after, after / before, seconds);
  }
  std::printf("clean render denoised: RMSE %.5f against itself\n",
              rootMeanSquareDifference(denoise(clean, features, denoiseOptions), clean));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: denoise_rmse SCENE.toml [THREADS]\n");
    return 2;
  }
  try {
    return run(argv[1], argc > 2 ? std::atoi(argv[2]) : 2);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}
