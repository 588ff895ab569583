// libFuzzer target: list-based gmsh .pos text (as GetDP writes its results) -> PosFile
// (readPosFromMemory): every element code, step counts, TIME lists, comments, numbers.
#include <cstddef>
#include <cstdint>
#include <span>

#include "lancer/mesh/pos/pos_reader.hpp"
#include "lancer/util/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const lancer::PosFile file = lancer::readPosFromMemory(
        std::span<const char>(reinterpret_cast<const char*>(data), size), "/fuzz/view.pos");
    (void)file;
  } catch (const lancer::InputError&) {
    // Expected for most inputs.
  }
  return 0;
}
