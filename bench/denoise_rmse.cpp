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

#include "lancer/render/denoiser.hpp"
#include "lancer/render/pixel_sampler.hpp"
#include "lancer/render/renderer.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/stopwatch.hpp"

namespace {

using namespace lancer;

// Box-Muller on the renderer's per-pixel hash: the same noise on every run and platform.
float gaussian(int x, int y, int channel) {
  const float u1 = std::max(sampleJitter(x, y, channel, 0), 1e-7f), u2 = sampleJitter(x, y, channel, 1);
  return std::sqrt(-2.0f * std::log(u1)) * std::cos(6.2831853f * u2);
}

double rmse(const Image& a, const Image& b) {
  double sum = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Vec3 d = a.at(x, y).rgb() - b.at(x, y).rgb();
      sum += dot(d, d) / 3.0;
    }
  return std::sqrt(sum / (static_cast<double>(a.width()) * a.height()));
}

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
    Image noisy = clean;
    for (int y = 0; y < clean.height(); ++y)
      for (int x = 0; x < clean.width(); ++x) {
        Rgba& p = noisy.at(x, y);
        p.r += sigma * gaussian(x, y, 0);
        p.g += sigma * gaussian(x, y, 1);
        p.b += sigma * gaussian(x, y, 2);
      }
    const Stopwatch time;
    const Image denoised = denoise(noisy, features, denoiseOptions);
    const double seconds = time.seconds();
    const double before = rmse(noisy, clean), after = rmse(denoised, clean);
    std::printf("| %.2f | %.4f | %.4f | %.2f | %.3f |\n", sigma, before, after, after / before, seconds);
  }
  std::printf("clean render denoised: RMSE %.5f against itself\n",
              rmse(denoise(clean, features, denoiseOptions), clean));
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
