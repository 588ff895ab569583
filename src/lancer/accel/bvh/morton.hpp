// The BVH build's first step (bvh/build.cpp): face references put in Morton order of their centroids
// and cut into small clusters of nearby faces along the order's cells, as HLBVH does (Pantaleoni &
// Luebke 2010; Garanzha, Pantaleoni & McAllister 2011), so that each cluster is built on its own.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/accel/bvh/build_parts.hpp"
#include "lancer/util/huge_page_array.hpp"

namespace lancer::bvh {

// References [begin, end) of the Morton order.
struct Cluster {
  std::uint32_t begin = 0, end = 0;
};

// `refs` reordered by the Morton code of their centroids (30 bits: 10 an axis over the centroids'
// box), equal codes in their order before (a stable sort, so the order depends on the faces alone),
// and the order's clusters: each the references of one Morton cell, halved until it holds at most
// `maxReferences` (references of one code, too many, in runs of `maxReferences`).
std::vector<Cluster> mortonClusters(std::vector<PrimRef>& refs, std::uint32_t maxReferences, int threads);

// gatherFaces and mortonClusters in one, with the same references, slivers and clusters, but the
// references made once, in Morton order (from sorted keys of face and code): the build's memory
// holds 16 bytes a face while it sorts and 40 after, not the 72 of both orders of references and
// the keys.
struct MortonFaces {
  HugePageArray<PrimRef> refs;
  std::vector<PackedTriangle> slivers;
  std::vector<Cluster> clusters;
};
MortonFaces gatherMortonFaces(std::span<const Vec3> positions, std::span<const MeshFace> faces,
                              std::uint32_t maxReferences, int threads);

}  // namespace lancer::bvh
