// The volume boundary search (mesh/msh/volume_skin.hpp) against a plain std::sort of every face's key:
// random elements over few nodes (faces shared by two, three or more elements), several volumes,
// every element shape, any thread count and buffer size; and the binary reader's fast path for
// volume blocks, which reads element records straight into the element array.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh/volume_skin.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

// The rule findVolumeBoundary states, the simplest way: sort (key, face) pairs, look at each run.
std::vector<VolumeBoundaryFace> referenceBoundary(const MshVolumeElements& elements,
                                                  const std::vector<std::uint64_t>& volumeOfGroup) {
  struct Keyed {
    MshFaceKey key;
    std::uint32_t face;
    bool operator<(const Keyed& other) const {
      return key < other.key || (key == other.key && face < other.face);
    }
  };
  std::vector<Keyed> keyed;
  for (std::uint64_t f = 0; f < elements.faceCount(); ++f) {
    const MshVolumeFace face = elements.face(f);
    keyed.push_back(
        {mshFaceKey(face.corner, face.corner[3] == kNoVertex ? 3 : 4), static_cast<std::uint32_t>(f)});
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<VolumeBoundaryFace> boundary;
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    while (j < keyed.size() && keyed[j].key == keyed[i].key) ++j;
    if (j == i + 1) boundary.push_back({keyed[i].face, kNoVertex});
    if (j == i + 2) {
      const std::uint64_t a = volumeOfGroup[elements.face(keyed[i].face).group];
      const std::uint64_t b = volumeOfGroup[elements.face(keyed[i + 1].face).group];
      if (a < b) boundary.push_back({keyed[i].face, keyed[i + 1].face});
      if (b < a) boundary.push_back({keyed[i + 1].face, keyed[i].face});
    }
    i = j;
  }
  std::sort(boundary.begin(), boundary.end(),
            [](const VolumeBoundaryFace& x, const VolumeBoundaryFace& y) { return x.face < y.face; });
  return boundary;
}

void expectSame(const std::vector<VolumeBoundaryFace>& actual,
                const std::vector<VolumeBoundaryFace>& expected, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    ASSERT_EQ(actual[i].face, expected[i].face) << what << ", boundary face " << i;
    ASSERT_EQ(actual[i].outer, expected[i].outer) << what << ", boundary face " << i;
  }
}

// `count` elements of random types among `types`, with distinct random nodes below `nodes`, in
// `groups` groups (runs of a few elements each).
MshVolumeElements randomElements(std::mt19937& random, std::size_t count, std::uint32_t nodes,
                                 const std::vector<int>& types, std::uint32_t groups) {
  MshVolumeElements elements;
  std::vector<std::uint32_t> pool(nodes);
  for (std::uint32_t i = 0; i < nodes; ++i) pool[i] = i;
  std::uint32_t group = 0;
  for (std::size_t e = 0; e < count; ++e) {
    const int type = types[random() % types.size()];
    const int nodeCount = mshElementType(type).nodeCount;
    for (int k = 0; k < nodeCount; ++k)
      std::swap(pool[static_cast<std::size_t>(k)], pool[k + random() % (nodes - k)]);
    if (random() % 8 == 0) group = static_cast<std::uint32_t>(random() % groups);
    elements.add(type, pool.data(), group, e);
  }
  return elements;
}

TEST(VolumeBoundary, EqualsASortOfEveryKeyForAnyThreadCountAndBuffer) {
  std::mt19937 random(7);
  // Few nodes: most faces meet a copy, many two or more (a broken mesh's faces in three elements).
  const struct {
    std::uint32_t nodes;
    std::vector<int> types;
  } cases[] = {{7, {4}}, {30, {4}}, {400, {4}}, {12, {5, 6, 7}}, {60, {4, 5, 6, 7, 11, 17}}};
  for (const auto& c : cases) {
    for (const std::uint32_t groups : {1U, 3U}) {
      const MshVolumeElements elements = randomElements(random, 6000, c.nodes, c.types, groups);
      const std::vector<std::uint64_t> volumeOfGroup = {5, 2, 5};
      const std::vector<VolumeBoundaryFace> expected = referenceBoundary(elements, volumeOfGroup);
      for (const int threads : {1, 2, 3})
        for (const std::size_t sliceBytes : {std::size_t{1}, std::size_t{4096}, kVolumeBoundarySliceBytes})
          expectSame(findVolumeBoundary(elements, c.nodes, volumeOfGroup, groups > 1, threads, sliceBytes),
                     expected,
                     "nodes " + std::to_string(c.nodes) + ", groups " + std::to_string(groups) +
                         ", threads " + std::to_string(threads) + ", slice " + std::to_string(sliceBytes));
    }
  }
}

TEST(VolumeBoundary, AFaceInThreeElementsIsInteriorAndTwoVolumesMeetAtAnInterface) {
  // Three tetrahedra on the triangle 0 1 2 (a broken mesh): the shared face is in none of the skin.
  MshVolumeElements three;
  const std::uint32_t tets[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 4}, {1, 0, 2, 5}};
  for (const auto& tet : tets) three.add(4, tet, 0, 0);
  const std::vector<VolumeBoundaryFace> skin =
      findVolumeBoundary(three, 6, std::vector<std::uint64_t>{1}, false, 2);
  EXPECT_EQ(skin.size(), 9U);
  for (const VolumeBoundaryFace& face : skin) {
    const MshVolumeFace corners = three.face(face.face);
    EXPECT_NE(mshFaceKey(corners.corner, 3), (MshFaceKey{0, 1, 2, kNoVertex})) << face.face;
    EXPECT_EQ(face.outer, kNoVertex);
  }
  // Two tetrahedra of two volumes on one triangle: the side of the smaller volume is kept.
  MshVolumeElements two;
  two.add(4, tets[0], 0, 0);
  two.add(4, tets[1], 1, 0);
  const std::vector<VolumeBoundaryFace> sides =
      findVolumeBoundary(two, 6, std::vector<std::uint64_t>{9, 4}, true, 1);
  ASSERT_EQ(sides.size(), 7U);
  const auto interface = std::find_if(sides.begin(), sides.end(),
                                      [](const VolumeBoundaryFace& f) { return f.outer != kNoVertex; });
  ASSERT_NE(interface, sides.end());
  EXPECT_EQ(interface->face, 4U);  // the second element's face 0 (its faces are 4 .. 7)
  EXPECT_EQ(interface->outer, 0U);
}

// A binary MSH 4.1 file of two tetrahedra (tags 7 and 8) on nodes 1 .. 5; `secondTetNode` is the
// second tetrahedron's last node.
std::string twoTetrahedra(std::uint64_t secondTetNode) {
  std::string bytes = "$MeshFormat\n4.1 1 8\n";
  const auto put = [&](const auto& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(value));
  };
  put(std::int32_t{1});
  bytes += "\n$EndMeshFormat\n$Nodes\n";
  for (const std::uint64_t v : {1, 5, 1, 5}) put(v);
  for (const std::int32_t v : {3, 1, 0}) put(v);
  put(std::uint64_t{5});
  for (std::uint64_t tag = 1; tag <= 5; ++tag) put(tag);
  const double points[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& p : points) put(p);
  bytes += "\n$EndNodes\n$Elements\n";
  for (const std::uint64_t v : {1, 2, 7, 8}) put(v);
  for (const std::int32_t v : {3, 1, 4}) put(v);
  put(std::uint64_t{2});
  for (const std::uint64_t v : {7, 1, 2, 3, 4}) put(v);
  for (const std::uint64_t v :
       {std::uint64_t{8}, std::uint64_t{1}, std::uint64_t{3}, std::uint64_t{2}, secondTetNode})
    put(v);
  bytes += "\n$EndElements\n";
  return bytes;
}

TEST(VolumeBoundary, BinaryTetrahedronBlocksGiveTheSkin) {
  const std::string bytes = twoTetrahedra(5);
  const Mesh mesh = readMshFromMemory(bytes, "two.msh", 2);
  EXPECT_EQ(mesh.source.volumeElements, 2U);
  EXPECT_EQ(mesh.source.skinFaces, 6U);
  EXPECT_EQ(mesh.faceCount(), 6U);
}

TEST(VolumeBoundaryBadInput, ABinaryTetrahedronNamingAMissingNodeIsReportedAtItsRecord) {
  const std::string bytes = twoTetrahedra(99);
  const std::string message = test::messageOf([&] { readMshFromMemory(bytes, "two.msh", 2); });
  EXPECT_NE(message.find("element 8 (4-node tetrahedron) uses node 99, which $Nodes does not define"),
            std::string::npos)
      << message;
  // The record of element 8: after the first tetrahedron's 40 bytes.
  const std::size_t second = bytes.find("$Elements\n") + 10 + 32 + 20 + 40;
  EXPECT_NE(message.find("two.msh:@" + std::to_string(second) + ":"), std::string::npos) << message;
}

}  // namespace
}  // namespace lancer
