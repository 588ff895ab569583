// libFuzzer target: OpenEXR environment maps and images -> readEnvironmentMap and readExr (with the
// albedo, normal and depth layers): the header, the chunk table, sizes the file or the memory budget
// cannot hold, non-finite values. The readers take a path, so each input is written to one scratch
// file under $TMPDIR (scripts/ci_hardening.sh points it at memory).
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lancer/image/environment_map.hpp"
#include "lancer/image/exr_io.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/memory_budget.hpp"

namespace {

const std::string& scratchFile() {
  static const std::string path = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp != nullptr ? tmp : "/tmp") + "/lancer-fuzz-exr-" + std::to_string(getpid()) +
           ".exr";
  }();
  return path;
}

}  // namespace

// A small budget: a header may ask for any size its chunks could hold, and the reader allocates and
// fills that much before it finds the chunks corrupt; 64 MiB keeps each input quick.
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  lancer::setMemoryBudget(64u << 20);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratchFile();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
  std::fclose(file);
  try {
    const lancer::HdrImage map = lancer::readEnvironmentMap(path);
    if (map.pixels.size() != static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height))
      std::abort();
    for (const lancer::Vec3& p : map.pixels)  // the map's promise: finite and not negative
      if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) || p.x < 0 || p.y < 0 || p.z < 0)
        std::abort();
  } catch (const lancer::InputError&) {
  }
  try {
    lancer::ExrLayers layers;
    const lancer::Image image = lancer::readExr(path, &layers);
    const std::size_t pixels =
        static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height());
    if ((!layers.albedo.empty() && layers.albedo.size() != pixels) ||
        (!layers.normal.empty() && layers.normal.size() != pixels) ||
        (!layers.depth.empty() && layers.depth.size() != pixels))
      std::abort();
  } catch (const lancer::InputError&) {
  }
  return 0;
}
