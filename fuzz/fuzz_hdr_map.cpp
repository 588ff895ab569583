// libFuzzer target: Radiance RGBE (.hdr) environment maps -> HdrImage (decodeRadianceHdr): the
// header lines, the size line, flat and run-length-encoded scanlines, sizes the data cannot hold.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "lancer/image/hdr_reader.hpp"
#include "lancer/util/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const lancer::HdrImage map =
        lancer::decodeRadianceHdr(std::string(reinterpret_cast<const char*>(data), size), "/fuzz/map.hdr");
    // A map that loads holds exactly its pixels.
    if (map.width <= 0 || map.height <= 0 ||
        map.pixels.size() != static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height))
      std::abort();
  } catch (const lancer::InputError&) {
    // Expected for most inputs.
  }
  return 0;
}
