// Meshes renumbered in Morton order (morton_renumbering.hpp) are the same meshes: every vertex and
// face is where it was with its corners, winding, groups, entities, edge masks and volume sides, and
// every field step (node, element and element-node values, in memory or left in the file) gives each
// vertex, face and corner the value it had; the new order is Morton's and depends on the mesh alone.
#include "lancer/mesh/morton_renumbering.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/util/morton_order.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

constexpr std::uint64_t kKeepAll = UINT64_MAX;

bool sameValue(float a, float b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void expectPermutation(const std::vector<std::uint32_t>& order, std::size_t count, const char* what) {
  ASSERT_EQ(order.size(), count) << what;
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(sorted[i], i) << what;
}

// Field `k` of `after` gives every vertex, face or corner of the renumbered mesh the value `before`
// gave it.
void expectSameField(const Mesh& before, const Mesh& after, std::size_t k, const MeshRenumbering& numbers) {
  const MeshField a = loadedField(before.fields[k]);
  const MeshField b = loadedField(after.fields[k]);
  const std::string what = fmt::format("field {} \"{}\" step {}", k, a.name, a.step);
  ASSERT_EQ(a.values.size(), b.values.size()) << what;
  EXPECT_EQ(b.isStored(), false);
  EXPECT_EQ(after.fields[k].isStored(), before.fields[k].isStored()) << what;
  const auto width = static_cast<std::size_t>(a.components);
  const auto expectItem = [&](std::size_t newItem, std::size_t oldItem) {
    for (std::size_t i = 0; i < width; ++i)
      ASSERT_TRUE(sameValue(b.values[newItem * width + i], a.values[oldItem * width + i]))
          << what << ": item " << newItem << " was " << oldItem;
  };
  const std::vector<std::uint32_t>& vertex = *numbers.originalVertex;
  const std::vector<std::uint32_t>& face = *numbers.originalFace;
  switch (a.at) {
    case FieldAt::kNode:
      for (std::size_t v = 0; v < vertex.size(); ++v) expectItem(v, vertex[v]);
      break;
    case FieldAt::kElement:
      for (std::size_t f = 0; f < face.size(); ++f) expectItem(f, face[f]);
      break;
    case FieldAt::kCorner:
      for (std::size_t f = 0; f < face.size(); ++f) {
        const MeshFace& now = after.faces[f];
        const MeshFace& was = before.faces[face[f]];
        for (int c = 0; c < now.cornerCount(); ++c)
          expectItem(f * kCornerSlots + cornerSlot(now, c), face[f] * kCornerSlots + cornerSlot(was, c));
      }
      break;
  }
}

void expectSameMesh(const Mesh& before, const Mesh& after, const MeshRenumbering& numbers) {
  const std::vector<std::uint32_t>& vertex = *numbers.originalVertex;
  const std::vector<std::uint32_t>& face = *numbers.originalFace;
  expectPermutation(vertex, before.positions.size(), "vertices");
  expectPermutation(face, before.faces.size(), "faces");
  ASSERT_EQ(after.positions.size(), before.positions.size());
  ASSERT_EQ(after.faces.size(), before.faces.size());
  for (std::size_t v = 0; v < vertex.size(); ++v) {
    ASSERT_EQ(after.positions[v].x, before.positions[vertex[v]].x) << "vertex " << v;
    ASSERT_EQ(after.positions[v].y, before.positions[vertex[v]].y) << "vertex " << v;
    ASSERT_EQ(after.positions[v].z, before.positions[vertex[v]].z) << "vertex " << v;
  }
  const auto perFace = [&](const auto& now, const auto& was, const char* what) {
    ASSERT_EQ(now.size(), was.size()) << what;
    if (was.empty()) return;
    for (std::size_t f = 0; f < face.size(); ++f) ASSERT_EQ(now[f], was[face[f]]) << what << " of face " << f;
  };
  for (std::size_t f = 0; f < face.size(); ++f) {
    const MeshFace& now = after.faces[f];
    const MeshFace& was = before.faces[face[f]];
    ASSERT_EQ(now.cornerCount(), was.cornerCount()) << "face " << f;
    for (int c = 0; c < now.cornerCount(); ++c)  // the same corners, in the same winding
      ASSERT_EQ(vertex[now.vertex[c]], was.vertex[c]) << "face " << f << " corner " << c;
  }
  perFace(after.facePhysicalTag, before.facePhysicalTag, "physical tag");
  perFace(after.faceEntityTag, before.faceEntityTag, "entity tag");
  perFace(after.faceEdgeMask, before.faceEdgeMask, "edge mask");
  perFace(after.volumeSides.side, before.volumeSides.side, "volume side");
  perFace(after.volumeSides.outerPhysicalTag, before.volumeSides.outerPhysicalTag, "outer physical tag");
  perFace(after.volumeSides.outerEntityTag, before.volumeSides.outerEntityTag, "outer entity tag");
  ASSERT_EQ(after.fields.size(), before.fields.size());
  for (std::size_t k = 0; k < before.fields.size(); ++k) expectSameField(before, after, k, numbers);
}

struct Fixture {
  const char* file;
  std::uint64_t residentFieldBytes;
};

class MortonRenumbering : public testing::TestWithParam<Fixture> {};

TEST_P(MortonRenumbering, KeepsEveryVertexFaceTagAndValue) {
  const Mesh before = readMsh(test::dataFile(GetParam().file), 1, GetParam().residentFieldBytes);
  Mesh after = before;
  const MeshRenumbering numbers = renumberInMortonOrder(after, 2);
  expectSameMesh(before, after, numbers);
  // The file's order was not Morton's: something moved (a test that cannot pass by doing nothing).
  std::vector<std::uint32_t> identity(before.faces.size());
  std::iota(identity.begin(), identity.end(), 0u);
  EXPECT_NE(*numbers.originalFace, identity);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, MortonRenumbering,
    testing::Values(Fixture{"render/bracket_coarse.msh", kKeepAll},
                    Fixture{"multimaterial/cube_sphere_v41.msh", kKeepAll},  // interfaces: volume sides
                    Fixture{"fields/node_quad8_v41_ascii.msh", kKeepAll},    // quads, added centres
                    Fixture{"fields/element_xy_v41_bin.msh", kKeepAll},
                    Fixture{"fields/element_xy_v41_bin.msh", 0},
                    Fixture{"element_node/tet_v41_bin.msh", kKeepAll},  // corner values: slots by rank
                    Fixture{"element_node/tet_v41_bin.msh", 0}, Fixture{"element_node/quad9_v41_bin.msh", 0},
                    Fixture{"results/cantilever.msh", 0}),  // steps left in the file, read back renumbered
    [](const testing::TestParamInfo<Fixture>& param) {
      std::string name = param.param.file;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name + (param.param.residentFieldBytes == 0 ? "_stored" : "");
    });

TEST(MortonRenumberingOrder, FacesAndVerticesFollowTheMortonCurveWhateverTheThreads) {
  const Mesh before = readMsh(test::dataFile("render/bracket_coarse.msh"));
  Mesh one = before, two = before;
  renumberInMortonOrder(one, 1);
  renumberInMortonOrder(two, 2);
  ASSERT_EQ(one.positions.size(), two.positions.size());
  for (std::size_t v = 0; v < one.positions.size(); ++v) ASSERT_EQ(one.positions[v], two.positions[v]);
  for (std::size_t f = 0; f < one.faces.size(); ++f)
    for (int c = 0; c < 4; ++c) ASSERT_EQ(one.faces[f].vertex[c], two.faces[f].vertex[c]);

  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Vec3& p : one.positions)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  const MortonGrid grid(lo, hi);
  std::uint32_t last = 0;
  for (const Vec3& p : one.positions) {
    const float at[3] = {p.x, p.y, p.z};
    ASSERT_GE(grid.code(at), last);
    last = grid.code(at);
  }
  last = 0;
  for (const MeshFace& face : one.faces) {
    Vec3 sum{};
    for (int c = 0; c < face.cornerCount(); ++c) sum = sum + one.positions[face.vertex[c]];
    const auto n = static_cast<float>(face.cornerCount());
    const float centroid[3] = {sum.x / n, sum.y / n, sum.z / n};
    ASSERT_GE(grid.code(centroid), last);
    last = grid.code(centroid);
  }
}

TEST(MortonRenumberingOrder, OnlyLargeMeshesAreRenumbered) {
  std::vector<Mesh> meshes{readMsh(test::dataFile("render/bracket_coarse.msh"))};
  const std::vector<MeshFace> faces = meshes.front().faces;
  EXPECT_LT(faces.size(), kMortonRenumberingMinFaces);
  EXPECT_EQ(renumberLargeMeshesInMortonOrder(meshes, 1), 0u);
  for (std::size_t f = 0; f < faces.size(); ++f)
    ASSERT_EQ(meshes.front().faces[f].vertex[0], faces[f].vertex[0]);
}

TEST(MortonRenumberingOrder, AnEmptyMeshStaysEmpty) {
  Mesh mesh;
  const MeshRenumbering numbers = renumberInMortonOrder(mesh, 1);
  EXPECT_TRUE(numbers.originalVertex->empty());
  EXPECT_TRUE(numbers.originalFace->empty());
}

}  // namespace
}  // namespace lancer
