// The binning of the BVH build's SAH split (bvh/build_parts.cpp): each reference's box and triangles
// added to the bin of its centroid on each axis. A kernel (util/isa.hpp): the x86-64-v3 copy grows a
// bin's whole box (lo and hi, 32 bytes) with one AVX min, max and blend; min and max being exact, both
// copies fill the same bins and the tree is the same byte for byte.
#pragma once

#include <cstddef>
#include <cstdint>

#include "lancer/accel/bvh/build_parts.hpp"

namespace lancer::bvh {

constexpr int kMaxBins = 32;

// The grid of a range's centroids (lanes x, y, z and a fourth lane of zeros), as build_parts.cpp's
// Grid holds it.
struct BinGrid {
  alignas(16) float origin[4];
  alignas(16) float scale[4];
  float last;  // the last bin, as a float
};

// Bins of three axes: box[(axis * kMaxBins + bin) * 8 ...] holds lo (x, y, z, unread) then hi
// (x, y, z, unread); triangles[bin * 4 + axis] the triangles. The bins are set up by the caller.
template <typename Isa>
void fillBins(const PrimRef* refs, std::size_t begin, std::size_t end, const BinGrid& grid, float* box,
              std::uint32_t* triangles);

}  // namespace lancer::bvh
