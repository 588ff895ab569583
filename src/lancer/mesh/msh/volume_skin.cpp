#include "lancer/mesh/msh/volume_skin.hpp"

#include <algorithm>

#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/util/huge_pages.hpp"

namespace lancer {
namespace {

// Face tables in gmsh's reference-element node order ("Node ordering" in the gmsh manual), each
// face listed counter-clockwise seen from outside. -1 ends a triangle.
constexpr int kTetFaces[4][4] = {{0, 2, 1, -1}, {0, 1, 3, -1}, {0, 3, 2, -1}, {1, 2, 3, -1}};
// Edge nodes of the 10-node tetrahedron's faces, in the same order (4: 0-1, 5: 1-2, 6: 2-0,
// 7: 3-0, 8: 3-2, 9: 3-1).
constexpr int kTet10FaceMids[4][3] = {{6, 5, 4}, {4, 9, 7}, {7, 8, 6}, {5, 8, 9}};
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
// Edge nodes of the 20- and 27-node hexahedron's faces, in the faces' corner order (8: 0-1, 9: 0-3,
// 10: 0-4, 11: 1-2, 12: 1-5, 13: 2-3, 14: 2-6, 15: 3-7, 16: 4-5, 17: 4-7, 18: 5-6, 19: 6-7), and the
// 27-node hexahedron's face nodes (20-25).
constexpr int kHex20FaceMids[6][4] = {{9, 13, 11, 8},   {16, 18, 19, 17}, {8, 12, 16, 10},
                                      {13, 15, 19, 14}, {10, 17, 15, 9},  {11, 14, 18, 12}};
constexpr int kHex27FaceCentres[6] = {20, 25, 21, 24, 22, 23};
constexpr int kPrismFaces[5][4] = {{0, 2, 1, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}};
constexpr int kPyramidFaces[5][4] = {
    {0, 3, 2, 1}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};

// The corners of face `local` of a table, kNoVertex for a triangle's fourth.
template <std::size_t N>
MshVolumeFace tableFace(const int (&table)[N][4], const std::uint32_t* nodes, int local,
                        std::uint32_t group) {
  MshVolumeFace face{{kNoVertex, kNoVertex, kNoVertex, kNoVertex},
                     {kNoVertex, kNoVertex, kNoVertex, kNoVertex},
                     kNoVertex,
                     group};
  const auto& corners = table[local];
  for (int c = 0; c < 4 && corners[c] >= 0; ++c) face.corner[c] = nodes[corners[c]];
  return face;
}

}  // namespace

MshFaceKey mshFaceKey(const std::uint32_t* corners, int cornerCount) {
  MshFaceKey key{kNoVertex, kNoVertex, kNoVertex, kNoVertex};
  // Insertion sort of at most four values (std::sort trips a false -Warray-bounds in g++ 12 here).
  for (int i = 0; i < cornerCount; ++i) {
    std::uint32_t value = corners[i];
    int j = i;
    for (; j > 0 && key[static_cast<std::size_t>(j - 1)] > value; --j)
      key[static_cast<std::size_t>(j)] = key[static_cast<std::size_t>(j - 1)];
    key[static_cast<std::size_t>(j)] = value;
  }
  return key;
}

std::optional<CellShape> mshVolumeShape(int type) {
  switch (type) {
    // Order 3 and up too: every gmsh volume element lists its corners first.
    case 4:
    case 11:
    case 29:
    case 30:
    case 31:
    case 32:
    case 33:
    case 71:
    case 72:
    case 73:
    case 74:
    case 75:
    case 79:
    case 80:
    case 81:
    case 82:
    case 83:
    case 137:
    case 139:
      return CellShape::kTetrahedron;
    case 5:
    case 12:
    case 17:
    case 92:
    case 93:
    case 94:
    case 95:
    case 96:
    case 97:
    case 98:
    case 99:
    case 100:
    case 101:
    case 102:
    case 103:
    case 104:
    case 105:
      return CellShape::kHexahedron;
    case 6:
    case 13:
    case 18:
    case 90:
    case 91:
    case 106:
    case 107:
    case 108:
    case 109:
    case 110:
    case 111:
    case 112:
    case 113:
    case 114:
    case 115:
    case 116:
    case 117:
      return CellShape::kPrism;
    case 7:
    case 14:
    case 19:
    case 118:
    case 119:
    case 120:
    case 121:
    case 122:
    case 123:
    case 124:
    case 125:
    case 126:
    case 127:
    case 128:
    case 129:
    case 130:
    case 131:
      return CellShape::kPyramid;
    default:
      return std::nullopt;
  }
}

const int (*volumeFaceCornerTable(int type))[4] {
  switch (*mshVolumeShape(type)) {
    case CellShape::kTetrahedron:
      return kTetFaces;
    case CellShape::kHexahedron:
      return kHexFaces;
    case CellShape::kPrism:
      return kPrismFaces;
    case CellShape::kPyramid:
      break;
  }
  return kPyramidFaces;
}

int volumeElementFaceCount(int type) {
  const std::optional<CellShape> shape = mshVolumeShape(type);
  if (!shape) return 0;
  switch (*shape) {
    case CellShape::kTetrahedron:
      return 4;
    case CellShape::kHexahedron:
      return 6;
    case CellShape::kPrism:
    case CellShape::kPyramid:
      break;
  }
  return 5;
}

MshVolumeFace volumeElementFace(int type, const std::uint32_t* nodes, int local, std::uint32_t group) {
  switch (*mshVolumeShape(type)) {
    case CellShape::kTetrahedron: {
      MshVolumeFace face = tableFace(kTetFaces, nodes, local, group);
      if (type == 11)
        for (int e = 0; e < 3; ++e) face.mid[e] = nodes[kTet10FaceMids[local][e]];
      return face;
    }
    case CellShape::kHexahedron: {
      MshVolumeFace face = tableFace(kHexFaces, nodes, local, group);
      if (type == 12 || type == 17) {
        for (int e = 0; e < 4; ++e) face.mid[e] = nodes[kHex20FaceMids[local][e]];
        if (type == 12) face.centre = nodes[kHex27FaceCentres[local]];
      }
      return face;
    }
    case CellShape::kPrism:
      return tableFace(kPrismFaces, nodes, local, group);
    case CellShape::kPyramid:
      break;
  }
  return tableFace(kPyramidFaces, nodes, local, group);
}

void MshVolumeElements::reserve(std::uint64_t elements, std::uint64_t nodes) {
  nodes_.reserve(nodes_.size() + nodes);
  adviseHugePages(nodes_);
  if (keepTags_) {
    tags_.reserve(tags_.size() + elements);
    adviseHugePages(tags_);
  }
}

void MshVolumeElements::newRun(int type, std::uint32_t group) {
  runs_.push_back(Run{type, mshElementType(type).nodeCount, volumeElementFaceCount(type), group,
                      elementCount_, faceCount_, nodes_.size()});
}

std::uint32_t* MshVolumeElements::appendNodes(int type, std::uint32_t group, std::uint64_t count,
                                              std::uint64_t** tags) {
  startElements(type, group, count);
  elementCount_ += count;
  const std::size_t first = nodes_.size();
  nodes_.resize(first + count * static_cast<std::uint64_t>(runs_.back().nodeCount));
  *tags = nullptr;
  if (keepTags_) {
    const std::size_t firstTag = tags_.size();
    tags_.resize(firstTag + count);
    *tags = tags_.data() + firstTag;
  }
  return nodes_.data() + first;
}

std::uint64_t MshVolumeElements::elementsIn(const Run& run) const {
  const auto index = static_cast<std::size_t>(&run - runs_.data());
  return (index + 1 < runs_.size() ? runs_[index + 1].firstElement : elementCount_) - run.firstElement;
}

const MshVolumeElements::Run& MshVolumeElements::runOfFace(std::uint64_t face) const {
  const auto after = std::upper_bound(runs_.begin(), runs_.end(), face,
                                      [](std::uint64_t f, const Run& run) { return f < run.firstFace; });
  return *(after - 1);
}

std::uint64_t MshVolumeElements::elementOfFace(const Run& run, std::uint64_t face) {
  return run.firstElement + (face - run.firstFace) / static_cast<std::uint64_t>(run.faceCount);
}

MshVolumeFace MshVolumeElements::face(std::uint64_t face) const {
  const Run& run = runOfFace(face);
  const auto local = static_cast<int>((face - run.firstFace) % static_cast<std::uint64_t>(run.faceCount));
  return volumeElementFace(run.type, elementNodes(run, elementOfFace(run, face)), local, run.group);
}

std::uint64_t MshVolumeElements::elementTagOfFace(std::uint64_t face) const {
  return tags_[elementOfFace(runOfFace(face), face)];
}

const std::uint32_t* MshVolumeElements::elementNodesOfFace(std::uint64_t face, int* nodeCount) const {
  const Run& run = runOfFace(face);
  *nodeCount = run.nodeCount;
  return elementNodes(run, elementOfFace(run, face));
}

}  // namespace lancer
