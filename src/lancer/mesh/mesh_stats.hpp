// Whole-mesh facts for `lancer info` and for tests: bounding box, surface area, face counts per
// physical group, and the shells (edge-connected face sets) with their closedness and orientation.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "lancer/mesh/mesh.hpp"

namespace lancer {

struct MeshShell {
  std::uint64_t faceCount = 0;
  double area = 0;
  // Every edge is shared by exactly two of the shell's faces.
  bool closed = false;
  // Every edge shared by two faces is traversed in opposite directions by them (and none by more).
  bool consistentlyOriented = false;
  // Volume enclosed, by the divergence theorem: > 0 when a closed, oriented shell's faces point out.
  double signedVolume = 0;
  // A closed, oriented shell nested inside an odd number of closed shells of its physical group
  // (shell_nesting.hpp): it bounds a cavity, and faces out of the material when signedVolume < 0.
  bool cavity = false;
  // Some of its faces are interfaces between two volumes (then never a cavity wall).
  bool interface = false;
};

// One directed edge of one face; sorting by key brings the faces that share an edge together.
struct FaceEdge {
  std::uint64_t key;  // (smaller vertex << 32) | larger vertex
  std::uint32_t face;
  bool forward;  // traversed from the smaller vertex to the larger
  bool operator<(const FaceEdge& other) const { return key < other.key; }
};

// The shells of a face set (faces joined through shared edges), shared by the statistics below and
// by shell orientation (shell_orientation.hpp), which needs the same edge table.
struct FaceShells {
  std::vector<FaceEdge> edges;            // every face's edges, sorted by key
  std::vector<std::uint32_t> shellOfFace;  // shells numbered in order of their first face
  std::vector<std::uint8_t> closed;        // per shell: every edge shared by exactly two faces
  std::vector<std::uint8_t> consistent;    // per shell: shared edges traversed in opposite directions
  std::size_t shellCount() const { return closed.size(); }
};

FaceShells findFaceShells(const std::vector<MeshFace>& faces);

struct MeshStats {
  Aabbd worldBounds;
  double area = 0;
  std::uint64_t triangles = 0;
  std::uint64_t quads = 0;
  // Faces that bound each physical group: a face counts under each of its groups, and an interface
  // for the volumes on both its sides.
  std::map<std::int32_t, std::uint64_t> facesByPhysicalTag;
  std::map<std::int32_t, std::uint64_t> interfaceFacesByPhysicalTag;
  // Interface faces per pair of volumes (smaller first): a volume is its physical tag (> 0), or minus
  // its elementary entity's tag when it is in no physical group (gmsh saving every element).
  std::map<std::pair<std::int64_t, std::int64_t>, std::uint64_t> interfaces;
  std::vector<MeshShell> shells;  // largest first
};

// Area of one face in the mesh's local frame (a quad: half the cross product of its diagonals).
double faceArea(const Mesh& mesh, std::size_t face);

MeshStats computeMeshStats(const Mesh& mesh);

}  // namespace lancer
