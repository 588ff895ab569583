// libFuzzer target: the gmsh .msh reader (every version, ASCII and binary) from bytes in memory.
// Bad input must end in InputError; anything else (crash, sanitizer report, other exception) is a bug.
// A file with fields is also read from a file with its steps left there (mesh_field.hpp: stored
// steps), and every step read back must be the values the memory read kept, bit for bit.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

#include "lancer/mesh/msh_reader.hpp"

namespace {

bool sameValues(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) return false;
  return true;
}

// The stored read of the same bytes: the same fields, read back to the same values.
void checkStoredSteps(std::span<const char> bytes, const lancer::Mesh& inMemory) {
  static const std::string path = "/tmp/lancer_fuzz_msh_" + std::to_string(::getpid()) + ".msh";
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return;
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  if (std::fclose(file) != 0 || !written) return;
  try {
    const lancer::Mesh stored = lancer::readMsh(path, 1, 0);
    if (stored.fields.size() != inMemory.fields.size()) __builtin_trap();
    for (std::size_t k = 0; k < stored.fields.size(); ++k) {
      const lancer::MeshField loaded = lancer::loadedField(stored.fields[k]);
      if (!sameValues(loaded.values, inMemory.fields[k].values)) __builtin_trap();
    }
  } catch (const lancer::InputError&) {
    __builtin_trap();  // the bytes the memory read took: a file of them must read as well
  }
  std::remove(path.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span bytes(reinterpret_cast<const char*>(data), size);
  try {
    const lancer::Mesh mesh = lancer::readMshFromMemory(bytes, "fuzz.msh");
    if (!mesh.fields.empty()) checkStoredSteps(bytes, mesh);
  } catch (const lancer::InputError&) {
    // The expected outcome for most inputs: a located error, which is what users see.
  }
  return 0;
}
