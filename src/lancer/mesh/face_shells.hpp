// The shells of a face set: faces joined through shared edges, with the sorted edge table that
// decides whether each shell is closed and consistently oriented (shell orientation, nesting, info).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/util/huge_page_array.hpp"

namespace lancer {

// One directed edge of one face, kept in the bucket of its smaller vertex (FaceShells::edgeStart):
// the bucket implies half of the key, so an edge takes 8 bytes, and the table's scatter half the
// writes. Sorting a bucket by the larger vertex brings the faces that share an edge together.
struct FaceEdge {
  std::uint32_t larger;          // the larger vertex
  std::uint32_t faceAndForward;  // face << 1 | traversed from the smaller vertex to the larger
  std::uint32_t face() const { return faceAndForward >> 1; }
  bool forward() const { return (faceAndForward & 1u) != 0; }
  bool operator<(const FaceEdge& other) const { return larger < other.larger; }
};

// The shells of a face set, shared by the mesh statistics (mesh_stats.hpp), shell orientation
// (shell_orientation.hpp), cavity finding (shell_nesting.hpp) and the regions of non-manifold shells
// (shell_regions.hpp), which need the same edge table.
struct FaceShells {
  // Every face's edges, by smaller vertex v in edges[edgeStart[v], edgeStart[v + 1]), each bucket
  // sorted by larger vertex (equal edges in face order); both empty when every shell is closed and
  // agrees (every edge of two faces traversed both ways), which is found without sorting them and
  // needs nothing more.
  HugePageArray<FaceEdge> edges;
  std::vector<std::uint32_t> edgeStart;
  std::vector<std::uint32_t> shellOfFace;  // shells numbered in order of their first face
  std::vector<std::uint8_t> closed;        // per shell: every edge shared by exactly two faces
  std::vector<std::uint8_t> consistent;    // per shell: shared edges traversed in opposite directions
  // Per closed shell: its faces can be turned to agree (each shared edge traversed both ways), and
  // per face of such a shell: whether to reverse it so it agrees with the shell's lowest face (in an
  // open shell the bit means nothing).
  std::vector<std::uint8_t> orientable;
  std::vector<std::uint8_t> flip;
  std::vector<std::uint8_t> bordered;  // per shell: an edge of one face only
  std::vector<std::uint8_t> branched;  // per shell: an edge shared by three or more faces
  std::size_t shellCount() const { return closed.size(); }
};

// Same result for any thread count (0: every core).
FaceShells findFaceShells(std::span<const MeshFace> faces, int threads = 0);

}  // namespace lancer
