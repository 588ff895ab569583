// Volume elements become their boundary: every element face is listed with outward winding; the
// faces that occur exactly once are the skin, and the faces shared by elements of two different
// volumes are the interfaces between them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/mesh/volume/volume_mesh.hpp"

namespace lancer {

// One face of a volume element, wound outward for a positively oriented element. For second-order
// tetrahedra and hexahedra, mid[] holds the face's edge nodes (corner0-corner1, corner1-corner2, ...)
// and centre a 27-node hexahedron's face node, so the skin is split like a 6-node triangle or a
// 9-node quad (an 8-node quad when centre is kNoVertex); mid[0] == kNoVertex otherwise (prisms and
// pyramids of second order use their corners only).
struct MshVolumeFace {
  std::uint32_t corner[4];
  std::uint32_t mid[4];
  std::uint32_t centre;
  std::uint32_t group;  // index into the assembler's (physical, entity) table
};

using MshFaceKey = std::array<std::uint32_t, 4>;  // sorted corner indices, kNoVertex last for triangles

MshFaceKey mshFaceKey(const std::uint32_t* corners, int cornerCount);

// The i-th node of a volume face in the order corner[0..3], mid[0..3], centre.
inline std::uint32_t volumeFaceNode(const MshVolumeFace& face, int i) {
  return i < 4 ? face.corner[i] : i < 8 ? face.mid[i - 4] : face.centre;
}

// The shape of a gmsh volume element type of any order, or nullopt for any other type.
std::optional<CellShape> mshVolumeShape(int type);

// How many faces a volume element type has (4 to 6), 0 for any type mshVolumeShape does not know.
int volumeElementFaceCount(int type);

// The corners of each face of a volume element type (one a row, its element positions; -1 ends a
// triangle), wound outward; for a type mshVolumeShape knows.
const int (*volumeFaceCornerTable(int type))[4];

// Face `local` (0 .. volumeElementFaceCount(type) - 1) of a volume element, in the element's own table
// order, with `group` as its group.
MshVolumeFace volumeElementFace(int type, const std::uint32_t* nodes, int local, std::uint32_t group);

// The volume elements of a mesh as read: their nodes (indices into the node table) in one array, in
// runs of one type and group, and their tags when asked. A volume face is numbered by its element and
// its place in the element's face table: the faces of element 0, then of element 1, ... (the order
// the skin keeps). Nothing is stored per face: the 4 to 6 faces of an element are made from its nodes
// when asked, so a mesh of millions of tetrahedra takes its node indices and little else.
class MshVolumeElements {
 public:
  struct Run {
    int type;
    int nodeCount;
    int faceCount;
    std::uint32_t group;
    std::uint64_t firstElement;
    std::uint64_t firstFace;
    std::uint64_t firstNode;
  };
  // Room for `elements` more elements of `nodes` nodes in all (and their tags when kept).
  void reserve(std::uint64_t elements, std::uint64_t nodes);
  // Appends one element (a type mshVolumeShape knows); the tag is kept when keepTags() was asked.
  void add(int type, const std::uint32_t* nodes, std::uint32_t group, std::uint64_t tag) {
    startElements(type, group, 1);
    ++elementCount_;
    nodes_.insert(nodes_.end(), nodes, nodes + runs_.back().nodeCount);
    if (keepTags_) tags_.push_back(tag);
  }
  // Appends `count` elements of one type and group; returns where their nodes go (count x the type's
  // node count, to be filled by the caller) and, when tags are kept, their tags' place.
  std::uint32_t* appendNodes(int type, std::uint32_t group, std::uint64_t count, std::uint64_t** tags);
  // Set before the first element: tags are kept (for element data and the kept volume).
  void keepTags() { keepTags_ = true; }

  bool empty() const { return runs_.empty(); }
  std::uint64_t elementCount() const { return elementCount_; }
  std::uint64_t faceCount() const { return faceCount_; }
  std::span<const Run> runs() const { return runs_; }
  std::uint64_t elementsIn(const Run& run) const;
  const std::uint32_t* elementNodes(const Run& run, std::uint64_t element) const {
    return nodes_.data() + run.firstNode +
           (element - run.firstElement) * static_cast<std::uint64_t>(run.nodeCount);
  }
  // The run that holds face `face`, and the element (its index) the face is of.
  const Run& runOfFace(std::uint64_t face) const;
  static std::uint64_t elementOfFace(const Run& run, std::uint64_t face);
  MshVolumeFace face(std::uint64_t face) const;
  // The tag and nodes of the element that face `face` belongs to (tags only when kept).
  std::uint64_t elementTagOfFace(std::uint64_t face) const;
  const std::uint32_t* elementNodesOfFace(std::uint64_t face, int* nodeCount) const;
  // Frees everything.
  void clear() { *this = MshVolumeElements(); }

 private:
  void startElements(int type, std::uint32_t group, std::uint64_t count) {
    if (runs_.empty() || runs_.back().type != type || runs_.back().group != group) newRun(type, group);
    faceCount_ += count * static_cast<std::uint64_t>(runs_.back().faceCount);
  }
  void newRun(int type, std::uint32_t group);

  std::vector<Run> runs_;
  std::vector<std::uint32_t> nodes_;
  std::vector<std::uint64_t> tags_;
  std::uint64_t elementCount_ = 0;
  std::uint64_t faceCount_ = 0;
  bool keepTags_ = false;
};

// One face of the volumes' boundary: `face` (an index into the volume faces) is the side kept, wound
// out of its element's volume; `outer` is the face of the other volume's element on an interface,
// kNoVertex on the skin.
struct VolumeBoundaryFace {
  std::uint32_t face;
  std::uint32_t outer;
};

// The faces that occur once among the elements' faces (skin) and the faces that occur twice with two
// different volumes (volumeOfGroup[group], any 64-bit identity per group); faces shared by two
// elements of one volume, or by more than two elements (a broken mesh), are interior. On an interface
// the kept side is the element of the smaller volume identity. `severalVolumes` false: every face is
// of one volume (then there are no interfaces). Ascending by `face`. The face keys are put in buckets
// by their smallest node (one counting pass and one scatter, both on `threads` threads), and each
// bucket, a few thousand keys that stay in cache, is sorted on its own: O(n log(n / buckets)), and
// the same result for any thread count. `nodeCount`: the node indices are below it. The keys are
// sorted a slice of buckets at a time in one buffer of at most `sliceBytes` (tests make it small).
inline constexpr std::size_t kVolumeBoundarySliceBytes = std::size_t{96} << 20;
std::vector<VolumeBoundaryFace> findVolumeBoundary(const MshVolumeElements& elements, std::size_t nodeCount,
                                                   std::span<const std::uint64_t> volumeOfGroup,
                                                   bool severalVolumes, int threads,
                                                   std::size_t sliceBytes = kVolumeBoundarySliceBytes);

}  // namespace lancer
