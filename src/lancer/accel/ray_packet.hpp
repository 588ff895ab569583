// Packets of rays for the kd-tree's packet queries: eight rays, usually coherent (a block of primary
// rays, or their shadow rays to one light), each with its own interval, traced down the tree together.
#pragma once

#include <cstdint>

#include "lancer/math/ray.hpp"

namespace lancer {

// Eight lanes: the width of an AVX2 register of floats.
inline constexpr int kPacketSize = 8;
inline constexpr std::uint32_t kAllLanes = (1u << kPacketSize) - 1;

// The rays of a packet, with t in (tMin[i], tMax[i]) for lane i; a query takes a lane mask saying
// which lanes hold rays (bit i for lane i).
// Lanes are left unconstructed (a query reads only those of its mask): the renderer makes two
// packets per primary sample, and zeroing their rays cost 3% of examples/demo.toml.
struct RayPacket {
  union {
    Ray ray[kPacketSize];
  };
  float tMin[kPacketSize];
  float tMax[kPacketSize];
  RayPacket() {}
};

}  // namespace lancer
