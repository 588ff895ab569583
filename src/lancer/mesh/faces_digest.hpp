// A digest of a face list's corners: two independent 64-bit mixes, so that lists with equal digests
// are the same faces (a chance of 2^-128 otherwise). An animation over warped steps compares frames'
// faces by it instead of holding a copy of the previous frame's (16 bytes a face).
#pragma once

#include <bit>
#include <cstdint>
#include <span>
#include <utility>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

inline std::pair<std::uint64_t, std::uint64_t> facesDigest(std::span<const MeshFace> faces) {
  std::uint64_t a = 0x9E3779B97F4A7C15ull ^ faces.size(), b = 0xC2B2AE3D27D4EB4Full + faces.size();
  for (const MeshFace& face : faces)
    for (const std::uint32_t v : face.vertex) {
      a = (a ^ v) * 0x100000001B3ull;                                            // FNV-1a's step
      b = std::rotl(b + v * 0xD6E8FEB86659FD93ull, 29) * 0x9FB21C651E98DF25ull;  // a multiply-rotate mix
    }
  return {a, b};
}

}  // namespace lancer
