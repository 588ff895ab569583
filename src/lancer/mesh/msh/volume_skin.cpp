#include "lancer/mesh/msh/volume_skin.hpp"

#include <algorithm>
#include <type_traits>

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

template <std::size_t N>
void appendFaces(const int (&table)[N][4], const std::uint32_t* nodes, std::uint32_t group,
                 std::vector<MshVolumeFace>& faces) {
  for (const auto& local : table) {
    MshVolumeFace face{{kNoVertex, kNoVertex, kNoVertex, kNoVertex},
                       {kNoVertex, kNoVertex, kNoVertex, kNoVertex},
                       kNoVertex,
                       group};
    for (int c = 0; c < 4 && local[c] >= 0; ++c) face.corner[c] = nodes[local[c]];
    faces.push_back(face);
  }
}

// Sorting the keys brings the two copies of every interior face together. With several volumes the
// face's group travels with its key (filled in the sequential pass), so telling an interface from an
// interior face reads no face again at random; with one volume the entry stays 20 bytes.
struct KeyedFace {
  MshFaceKey key;
  std::uint32_t face;
  bool operator<(const KeyedFace& other) const { return key < other.key; }
};

struct KeyedGroupedFace {
  MshFaceKey key;
  std::uint32_t face;
  std::uint32_t group;
  bool operator<(const KeyedGroupedFace& other) const { return key < other.key; }
};

template <typename Keyed>
std::vector<VolumeBoundaryFace> boundaryOf(std::span<const MshVolumeFace> faces,
                                           std::span<const std::uint64_t> volumeOfGroup) {
  std::vector<Keyed> keyed(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const int corners = faces[i].corner[3] == kNoVertex ? 3 : 4;
    keyed[i].key = mshFaceKey(faces[i].corner, corners);
    keyed[i].face = static_cast<std::uint32_t>(i);
    if constexpr (std::is_same_v<Keyed, KeyedGroupedFace>) keyed[i].group = faces[i].group;
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<VolumeBoundaryFace> boundary;
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    while (j < keyed.size() && keyed[j].key == keyed[i].key) ++j;
    if (j == i + 1) {
      boundary.push_back({keyed[i].face, kNoVertex});
    } else if constexpr (std::is_same_v<Keyed, KeyedGroupedFace>) {
      const Keyed& a = keyed[i];
      const Keyed& b = keyed[i + 1];
      if (j == i + 2 && a.group != b.group) {
        const std::uint64_t volumeA = volumeOfGroup[a.group], volumeB = volumeOfGroup[b.group];
        if (volumeA < volumeB) boundary.push_back({a.face, b.face});
        if (volumeB < volumeA) boundary.push_back({b.face, a.face});
      }
    }
    i = j;
  }
  std::sort(boundary.begin(), boundary.end(),
            [](const VolumeBoundaryFace& x, const VolumeBoundaryFace& y) { return x.face < y.face; });
  return boundary;
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

void appendVolumeElementFaces(int type, const std::uint32_t* nodes, std::uint32_t group,
                              std::vector<MshVolumeFace>& faces) {
  const std::optional<CellShape> shape = mshVolumeShape(type);
  if (!shape) return;
  switch (*shape) {
    case CellShape::kTetrahedron:
      appendFaces(kTetFaces, nodes, group, faces);
      if (type == 11) {
        for (int f = 0; f < 4; ++f) {
          MshVolumeFace& face = faces[faces.size() - 4 + static_cast<std::size_t>(f)];
          for (int e = 0; e < 3; ++e) face.mid[e] = nodes[kTet10FaceMids[f][e]];
        }
      }
      break;
    case CellShape::kHexahedron:
      appendFaces(kHexFaces, nodes, group, faces);
      if (type == 12 || type == 17) {
        for (int f = 0; f < 6; ++f) {
          MshVolumeFace& face = faces[faces.size() - 6 + static_cast<std::size_t>(f)];
          for (int e = 0; e < 4; ++e) face.mid[e] = nodes[kHex20FaceMids[f][e]];
          if (type == 12) face.centre = nodes[kHex27FaceCentres[f]];
        }
      }
      break;
    case CellShape::kPrism:
      appendFaces(kPrismFaces, nodes, group, faces);
      break;
    case CellShape::kPyramid:
      appendFaces(kPyramidFaces, nodes, group, faces);
      break;
  }
}

std::vector<VolumeBoundaryFace> findVolumeBoundary(std::span<const MshVolumeFace> faces,
                                                   std::span<const std::uint64_t> volumeOfGroup,
                                                   bool severalVolumes) {
  return severalVolumes ? boundaryOf<KeyedGroupedFace>(faces, volumeOfGroup)
                        : boundaryOf<KeyedFace>(faces, {});
}

}  // namespace lancer
