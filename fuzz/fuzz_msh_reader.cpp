// libFuzzer target: the gmsh .msh reader (every version, ASCII and binary) from bytes in memory.
// Bad input must end in InputError; anything else (crash, sanitizer report, other exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "lancer/mesh/msh_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const lancer::Mesh mesh =
        lancer::readMshFromMemory(std::span(reinterpret_cast<const char*>(data), size), "fuzz.msh");
    (void)mesh;
  } catch (const lancer::InputError&) {
    // The expected outcome for most inputs: a located error, which is what users see.
  }
  return 0;
}
