// Build statistics of an acceleration structure, for `lancer info --accel` and the benchmarks:
// shape of the tree, its SAH cost, the time it took to build and the memory it holds.
#pragma once

#include <cstdint>
#include <string>

namespace lancer {

struct AccelStats {
  std::string kind;             // one of kAccelNames (accelerator.hpp)
  std::uint64_t faces = 0;      // mesh faces (a quad is one face)
  std::uint64_t triangles = 0;  // primitives in the structure (a quad is two triangles)
  std::uint64_t nodes = 0;      // inner nodes + leaves
  std::uint64_t leaves = 0;
  std::uint64_t emptyLeaves = 0;
  std::uint64_t depth = 0;               // deepest leaf; the root has depth 0
  std::uint64_t triangleReferences = 0;  // sum over leaves of their triangle counts
  double meanTrianglesPerLeaf = 0;       // over non-empty leaves
  double sahCost = 0;                    // expected cost of a random ray, in the build's cost units
  double buildSeconds = 0;
  std::uint64_t bytes = 0;  // nodes + leaf index array + precomputed triangles

  double bytesPerTriangle() const { return triangles ? double(bytes) / double(triangles) : 0.0; }
  double buildMillionTrianglesPerSecond() const {
    return buildSeconds > 0 ? double(triangles) / buildSeconds * 1e-6 : 0.0;
  }
};

}  // namespace lancer
