// The error of a `--look` render against a high-sample reference of the same look, for bands of rows
// (a 4096-sample reference of a whole 1080p frame takes hours on 2 cores): renders the chosen bands
// of the quick look of MESH at two sample counts (the reference and a quarter of it), reads the
// candidate (an EXR of the same look and size: its radiance), and prints the RMSE of the candidate
// against the reference in linear radiance and in sRGB display values (clamped to [0, 1]), with the
// reference's own noise estimated from the two references (nested Sobol' prefixes: the difference of
// the n/4- and n-sample means has variance 3 sigma^2 / n) and subtracted.
//   build/bench/look_reference MESH CANDIDATE.exr[,MORE.exr] LOOK WIDTH HEIGHT BANDS SAMPLES THREADS
// LOOK_REFERENCE_CACHE=DIR keeps the references rendered (an EXR per band and sample count) for
// the next run.
//   e.g. look_reference bench/data/bracket_1m.msh studio.exr studio 1920 1080 8,17,25 1024 2
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "lancer/image/exr_io.hpp"
#include "lancer/image/pixel_encoding.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/util/stopwatch.hpp"

namespace {

using namespace lancer;

struct Errors {
  double linear = 0, display = 0;
  long long count = 0;
  void add(const Vec3& a, const Vec3& b) {
    for (int c = 0; c < 3; ++c) {
      const float x = c == 0 ? a.x : c == 1 ? a.y : a.z, y = c == 0 ? b.x : c == 1 ? b.y : b.z;
      linear += (x - y) * (x - y);
      const float dx = srgbFromLinear(std::clamp(x, 0.0f, 1.0f)),
                  dy = srgbFromLinear(std::clamp(y, 0.0f, 1.0f));
      display += (dx - dy) * (dx - dy);
    }
    count += 3;
  }
  double linearRms() const { return std::sqrt(linear / count); }
  double displayRms() const { return std::sqrt(display / count); }
};

int run(int argc, char** argv) {
  if (argc != 9) {
    std::fprintf(stderr,
                 "usage: look_reference MESH CANDIDATE.exr LOOK WIDTH HEIGHT BANDS SAMPLES THREADS\n");
    return 2;
  }
  const std::string meshPath = argv[1], candidatePath = argv[2], lookName = argv[3];
  const int width = std::stoi(argv[4]), height = std::stoi(argv[5]), samples = std::stoi(argv[7]),
            threads = std::stoi(argv[8]);
  std::vector<int> bands;
  std::stringstream list(argv[6]);
  for (std::string item; std::getline(list, item, ',');) bands.push_back(std::stoi(item));

  RenderRequest request;
  Mesh mesh = readMsh(meshPath);
  request.description = quickLookScene(meshPath, mesh);
  request.quickLookMesh = std::move(mesh);
  request.overrides.width = width;
  request.overrides.height = height;
  for (std::size_t i = 0; i < kLookNames.size(); ++i)
    if (kLookNames[i] == lookName) request.overrides.look = static_cast<Look>(i);
  request.threads = threads;
  const PreparedRender prepared = prepareRender(std::move(request));
  std::vector<std::string> candidatePaths;
  std::stringstream paths(candidatePath);
  for (std::string item; std::getline(paths, item, ',');) candidatePaths.push_back(item);
  std::vector<Image> candidates;
  for (const std::string& path : candidatePaths) {
    candidates.push_back(readExr(path));
    if (candidates.back().width() != width || candidates.back().height() != height) {
      std::fprintf(stderr, "%s is not %dx%d\n", path.c_str(), width, height);
      return 2;
    }
  }
  RenderOptions options;
  options.threads = threads;
  std::vector<Errors> candidateErrors(candidates.size());
  Errors referenceSpread;
  const Stopwatch stopwatch;
  for (const int band : bands) {
    std::vector<Image> references;
    for (const int n : {samples / 4, samples}) {
      // LOOK_REFERENCE_CACHE=DIR keeps each band's reference as an EXR there, for the next candidates.
      const char* cache = std::getenv("LOOK_REFERENCE_CACHE");
      const std::string cached = cache == nullptr
                                     ? std::string()
                                     : fmt::format("{}/{}-{}-{}x{}-band{}-{}.exr", cache,
                                                   std::filesystem::path(meshPath).stem().string(), lookName,
                                                   width, height, band, n);
      if (!cached.empty() && std::filesystem::exists(cached)) {
        references.push_back(readExr(cached));
        continue;
      }
      RenderSettings settings = prepared.settings();
      settings.samples = n;
      settings.noise = 0;
      settings.denoise = false;
      references.push_back(Renderer(prepared.scene, prepared.accelerator, prepared.camera, settings)
                               .renderRows(BandRange{band, 1}, options));
      if (!cached.empty()) writeExr(cached, references.back());
    }
    const Image& reference = references[1];
    for (int y = 0; y < reference.height(); ++y)
      for (int x = 0; x < width; ++x) {
        for (std::size_t c = 0; c < candidates.size(); ++c)
          candidateErrors[c].add(candidates[c].at(x, band * kTileSize + y).rgb(), reference.at(x, y).rgb());
        referenceSpread.add(references[0].at(x, y).rgb(), reference.at(x, y).rgb());
      }
    std::fprintf(stderr, "band %d done, %.1f s\n", band, stopwatch.seconds());
  }
  // sigma^2 / n = spread^2 / 3: the reference's own error, taken out of the candidate's in quadrature.
  auto corrected = [](double measured, double spread) {
    const double own2 = spread * spread / 3.0;
    return std::sqrt(std::max(0.0, measured * measured - own2));
  };
  fmt::print("bands {} ({} pixels), reference {} samples/pixel, {:.1f} s\n", argv[6],
             referenceSpread.count / 3, samples, stopwatch.seconds());
  fmt::print("reference's own RMSE (estimated): linear {:.5f}, display {:.5f}\n",
             referenceSpread.linearRms() / std::sqrt(3.0), referenceSpread.displayRms() / std::sqrt(3.0));
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const Errors& e = candidateErrors[c];
    fmt::print(
        "{}: RMSE vs reference linear {:.5f}, display {:.5f}; reference noise removed: linear {:.5f}, "
        "display {:.5f}\n",
        candidatePaths[c], e.linearRms(), e.displayRms(),
        corrected(e.linearRms(), referenceSpread.linearRms()),
        corrected(e.displayRms(), referenceSpread.displayRms()));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "look_reference: %s\n", e.what());
    return 1;
  }
}
