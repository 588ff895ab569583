// libFuzzer target: TOML scene text -> checked SceneDescription (parseScene). Meshes named by the scene
// are not read here (scene_builder does that); the msh reader has its own target.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const lancer::SceneDescription scene =
        lancer::parseScene(std::string_view(reinterpret_cast<const char*>(data), size), "/fuzz/scene.toml");
    (void)scene;
  } catch (const lancer::InputError&) {
    // Expected for most inputs.
  }
  return 0;
}
