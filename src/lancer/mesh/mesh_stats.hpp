// Whole-mesh facts for `lancer info` and for tests: bounding box, surface area, face counts per
// physical group, and the shells (face_shells.hpp) with their closedness, orientation and volume.
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

MeshStats computeMeshStats(const Mesh& mesh);

}  // namespace lancer
