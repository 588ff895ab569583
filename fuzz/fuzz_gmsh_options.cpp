// libFuzzer target: gmsh options files (part.msh.opt, "File > Save Model Options") -> the view
// (readGmshView) and its camera for a unit model, and the post-processing views' options
// (readGmshPostViews). The readers take a path, so each input is written to one scratch file under
// $TMPDIR (scripts/ci_hardening.sh points it at memory).
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lancer/scene/results/gmsh_post_options.hpp"
#include "lancer/scene/results/gmsh_view.hpp"
#include "lancer/util/input_error.hpp"

namespace {

const std::string& scratchFile() {
  static const std::string path = [] {
    const char* tmp = std::getenv("TMPDIR");
    return std::string(tmp != nullptr ? tmp : "/tmp") + "/lancer-fuzz-opt-" + std::to_string(getpid()) +
           ".opt";
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratchFile();
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
  std::fclose(file);
  try {
    const lancer::GmshView view = lancer::readGmshView(path);
    lancer::Aabbd unit;
    unit.extend(lancer::Vec3d{0, 0, 0});
    unit.extend(lancer::Vec3d{1, 1, 1});
    (void)lancer::gmshViewCamera(view, unit, 4.0 / 3.0);
  } catch (const lancer::InputError&) {
  }
  try {
    (void)lancer::readGmshPostViews(path);
  } catch (const lancer::InputError&) {
  }
  return 0;
}
