// $ElementNodeData read from files gmsh wrote (scripts/make_element_node_fixtures.py): a cube of
// tetrahedra and a square of second-order quads and triangles, each with f = x + 2y (+ 3z) both as
// $NodeData ("f") and at every element's nodes ("g"). Every face corner of "g" must hold f at its
// vertex, whatever the MSH version and encoding, on volume skins and split second-order faces; a
// field constant per element ("jump") keeps its jumps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

const MeshField& fieldNamed(const Mesh& mesh, const std::string& name, int step = 0) {
  for (const MeshField& field : mesh.fields)
    if (field.name == name && field.step == step) return field;
  ADD_FAILURE() << "no field " << name << " step " << step << " in " << mesh.source.path;
  return mesh.fields.front();
}

// g's value at corner c of face f.
float cornerValue(const MeshField& g, const Mesh& mesh, std::size_t f, int c, int component = 0) {
  const auto slot = static_cast<std::size_t>(cornerSlot(mesh.faces[f], c));
  return g.values[(f * kCornerSlots + slot) * static_cast<std::size_t>(g.components) +
                  static_cast<std::size_t>(component)];
}

void expectCornersHoldNodeValues(const Mesh& mesh, float scale) {
  const MeshField& f = fieldNamed(mesh, "f");
  const MeshField& g = fieldNamed(mesh, "g", scale == 1 ? 0 : 1);
  ASSERT_EQ(g.at, FieldAt::kCorner);
  ASSERT_EQ(g.itemCount(), mesh.faceCount() * kCornerSlots);
  for (std::size_t face = 0; face < mesh.faceCount(); ++face) {
    const MeshFace& corners = mesh.faces[face];
    for (int c = 0; c < corners.cornerCount(); ++c)
      EXPECT_NEAR(cornerValue(g, mesh, face, c), scale * f.values[corners.vertex[c]], 1e-5)
          << "face " << face << " corner " << c;
    if (!corners.isQuad()) {
      EXPECT_TRUE(std::isnan(g.values[face * kCornerSlots + 3])) << "face " << face;
    }
  }
}

class ElementNodeDataTest : public testing::TestWithParam<const char*> {};

TEST_P(ElementNodeDataTest, EveryCornerHoldsItsElementsValueAtThatNode) {
  const Mesh mesh = readMsh(test::dataFile(std::string("element_node/") + GetParam()));
  EXPECT_TRUE(mesh.source.warnings.empty()) << mesh.source.warnings.front();
  expectCornersHoldNodeValues(mesh, 1);
  // The second step, at its own time.
  expectCornersHoldNodeValues(mesh, 2);
  EXPECT_DOUBLE_EQ(fieldNamed(mesh, "g", 1).time, 0.5);
}

INSTANTIATE_TEST_SUITE_P(AllEncodings, ElementNodeDataTest,
                         testing::Values("tet_v22_ascii.msh", "tet_v22_bin.msh", "tet_v41_ascii.msh",
                                         "tet_v41_bin.msh", "quad9_v41_bin.msh"),
                         [](const auto& param) { return test::fixtureTestName(param.param); });

TEST(ElementNodeData, AFieldThatJumpsKeepsEachElementsOwnValue) {
  const Mesh mesh = readMsh(test::dataFile("element_node/tet_v41_bin.msh"));
  const MeshField& jump = fieldNamed(mesh, "jump");
  const MeshField& perElement = fieldNamed(mesh, "jumpe");
  ASSERT_EQ(perElement.at, FieldAt::kElement);
  // Each corner has its face's element value; a vertex shared by faces of different elements has
  // different values on them (the jumps a node average would smooth away).
  std::vector<float> seen(mesh.positions.size(), NAN);
  bool jumps = false;
  for (std::size_t face = 0; face < mesh.faceCount(); ++face)
    for (int c = 0; c < mesh.faces[face].cornerCount(); ++c) {
      const float value = cornerValue(jump, mesh, face, c);
      EXPECT_EQ(value, perElement.values[face]) << "face " << face;
      float& first = seen[mesh.faces[face].vertex[c]];
      if (std::isnan(first)) first = value;
      jumps = jumps || first != value;
    }
  EXPECT_TRUE(jumps);
}

TEST(ElementNodeData, VertexMeansOfAContinuousVectorAreItsNodeValues) {
  const Mesh mesh = readMsh(test::dataFile("element_node/tet_v22_ascii.msh"));
  const MeshField means = vertexMeans(mesh, fieldNamed(mesh, "u"));
  ASSERT_EQ(means.at, FieldAt::kNode);
  ASSERT_EQ(means.values.size(), 3 * mesh.positions.size());
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(v);
    EXPECT_NEAR(means.values[3 * v], 0.1 * p.x, 1e-6);
    EXPECT_NEAR(means.values[3 * v + 1], 0.2 * p.y, 1e-6);
    EXPECT_EQ(means.values[3 * v + 2], 0.0f);
  }
}

// GetDP's -v2 output (scripts/make_getdp_fixtures.sh): MSH 2.2 files of $ElementNodeData on
// triangles. The potential az is continuous (nodal): every corner at a vertex agrees. The flux
// density b = curl az lies in the plane and jumps between elements.
TEST(ElementNodeData, GetDpsOwnOutput) {
  const Mesh az = readMsh(test::dataFile("getdp/magnet_v2_az.pos"));
  ASSERT_EQ(az.fields.size(), 1u);
  EXPECT_EQ(az.fields[0].name, "az");
  ASSERT_EQ(az.fields[0].at, FieldAt::kCorner);
  const MeshField means = vertexMeans(az, az.fields[0]);
  for (std::size_t face = 0; face < az.faceCount(); ++face)
    for (int c = 0; c < 3; ++c) {
      const float mean = means.values[az.faces[face].vertex[c]];
      EXPECT_NEAR(cornerValue(az.fields[0], az, face, c), mean, 1e-6f * std::abs(mean) + 1e-12f);
    }
  const Mesh b = readMsh(test::dataFile("getdp/magnet_v2_b.pos"));
  ASSERT_EQ(b.fields.size(), 1u);
  const MeshField& field = b.fields[0];
  ASSERT_EQ(field.components, 3);
  bool jumps = false;
  for (std::size_t face = 0; face < b.faceCount(); ++face)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(cornerValue(field, b, face, c, 2), 0.0f);  // in the plane
  const MeshField bMeans = vertexMeans(b, field);
  for (std::size_t face = 0; face < b.faceCount() && !jumps; ++face)
    jumps = std::abs(cornerValue(field, b, face, 0) - bMeans.values[3 * b.faces[face].vertex[0]]) > 1e-3f;
  EXPECT_TRUE(jumps);
}

TEST(ElementNodeData, StoredStepsReadBackTheSameValues) {
  const std::string path = test::dataFile("element_node/tet_v41_bin.msh");
  const Mesh inMemory = readMsh(path);
  const Mesh stored = readMsh(path, 0, 0);  // every step left in the file
  ASSERT_EQ(inMemory.fields.size(), stored.fields.size());
  for (std::size_t i = 0; i < stored.fields.size(); ++i) {
    ASSERT_TRUE(stored.fields[i].isStored());
    const MeshField loaded = loadedField(stored.fields[i]);
    EXPECT_EQ(loaded.at, inMemory.fields[i].at);
    ASSERT_EQ(loaded.values.size(), inMemory.fields[i].values.size());
    for (std::size_t k = 0; k < loaded.values.size(); ++k)
      if (!std::isnan(inMemory.fields[i].values[k])) {
        EXPECT_EQ(loaded.values[k], inMemory.fields[i].values[k]);
      }
  }
}

// Records tagged 1..N in order (as gmsh writes them) are read without a table per record; records
// in another order, or of other node counts, switch the tables on where the run breaks. Moving the
// first record of "g" after its 50th (the run broken at the 50th record read) and reversing them
// all (broken at the second) must put the same values on the same corners.
TEST(ElementNodeData, RecordsOutOfOrderGiveTheSameValues) {
  const std::string path = test::dataFile("element_node/tet_v41_ascii.msh");
  const std::string text = test::readText(path);
  const Mesh expected = readMsh(path);
  const std::size_t section = text.find("$ElementNodeData");
  const std::size_t header = text.find("\n101\n", section) + 5;  // the record count, then the records
  const std::size_t end = text.find("$End", header);
  std::vector<std::string> records;
  for (std::size_t at = header; at < end; at = text.find('\n', at) + 1)
    records.push_back(text.substr(at, text.find('\n', at) + 1 - at));
  ASSERT_EQ(records.size(), 101u);
  ASSERT_EQ(records.front().rfind("1 4 ", 0), 0u);
  std::vector<std::string> moved = records;
  std::rotate(moved.begin(), moved.begin() + 1, moved.begin() + 50);
  std::vector<std::string> reversed(records.rbegin(), records.rend());
  for (const auto& order : {moved, reversed}) {
    std::string edited = text.substr(0, header);
    for (const std::string& record : order) edited += record;
    edited += text.substr(end);
    const Mesh mesh = readMshFromMemory(std::span<const char>(edited.data(), edited.size()), "edited.msh");
    const MeshField& want = fieldNamed(expected, "g");
    const MeshField& got = fieldNamed(mesh, "g");
    ASSERT_EQ(got.values.size(), want.values.size());
    EXPECT_EQ(std::memcmp(got.values.data(), want.values.data(), want.values.size() * sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(fieldNamed(mesh, "g", 1).values.data(), fieldNamed(expected, "g", 1).values.data(),
                          want.values.size() * sizeof(float)),
              0);
  }
}

}  // namespace
}  // namespace lancer
