// The BVH of a mesh as a fingerprint: an FNV-1a hash of its nodes and leaf words, with its SAH cost
// and the build's wall time, so that a change to the build can show that it makes the same tree
// (same hash on any thread count, before and after) and how long it took.
//   bvh_tree_hash MESH [threads] [repetitions] [--renumber]
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "lancer/accel/bvh/bvh.hpp"
#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/morton_renumbering.hpp"

namespace {

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 0x100000001b3ull;
  return hash;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bvh_tree_hash MESH [threads] [repetitions] [--renumber]\n");
    return 2;
  }
  try {
    const int threads = argc > 2 ? std::stoi(argv[2]) : 0;
    const int repetitions = argc > 3 ? std::stoi(argv[3]) : 1;
    lancer::Mesh mesh = lancer::readMeshFile(argv[1], threads);
    if (argc > 4 && std::strcmp(argv[4], "--renumber") == 0) lancer::renumberInMortonOrder(mesh, threads);
    lancer::BvhBuildOptions options;
    options.threads = threads;
    for (int r = 0; r < repetitions; ++r) {
      const lancer::Bvh bvh = lancer::Bvh::build(mesh.positions, mesh.faces, options);
      std::uint64_t hash = 0xcbf29ce484222325ull;
      hash = fnv1a(bvh.nodes().data(), bvh.nodes().size_bytes(), hash);
      hash = fnv1a(bvh.leafWords().data(), bvh.leafWords().size_bytes(), hash);
      hash = fnv1a(bvh.slivers().data(), bvh.slivers().size_bytes(), hash);
      std::printf("hash %016llx nodes %zu leaf_words %zu sah %.4f build_s %.4f\n",
                  static_cast<unsigned long long>(hash), bvh.nodes().size(), bvh.leafWords().size(),
                  bvh.stats().sahCost, bvh.stats().buildSeconds);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bvh_tree_hash: %s\n", e.what());
    return 1;
  }
  return 0;
}
