// $NodeData read from files gmsh wrote (scripts/make_field_fixtures.sh): the unit square with the
// field x + 2 y, so the value at every mesh vertex must be x + 2 y of that vertex, whatever the MSH
// version, encoding and node renumbering.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "lancer/mesh/msh_reader.hpp"

namespace lancer {
namespace {

std::string fieldFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/fields/" + name;
}

// The fixtures' one field: "temperature", one component, step 0, with x + 2 y of `pointOf(i)` at
// every item i (a vertex for node data, a face for element data).
template <typename PointOf>
void expectXPlus2YField(const Mesh& mesh, bool perElement, std::size_t items, PointOf pointOf) {
  const FieldAt at = perElement ? FieldAt::kElement : FieldAt::kNode;
  ASSERT_EQ(mesh.fields.size(), 1u);
  const MeshField& field = mesh.fields[0];
  EXPECT_EQ(field.name, "temperature");
  EXPECT_EQ(field.at, at);
  EXPECT_EQ(field.components, 1);
  EXPECT_EQ(field.step, 0);
  ASSERT_EQ(field.itemCount(), items);
  for (std::size_t i = 0; i < items; ++i) {
    const Vec3d p = pointOf(i);
    EXPECT_NEAR(field.scalar(i), p.x + 2 * p.y, 1e-5) << (perElement ? "face " : "vertex ") << i;
  }
}

class NodeDataTest : public testing::TestWithParam<const char*> {};

TEST_P(NodeDataTest, ValuesLandOnTheirVertices) {
  const Mesh mesh = readMsh(fieldFixture(GetParam()));
  EXPECT_EQ(mesh.positions.size(), 25u);
  expectXPlus2YField(mesh, false, mesh.positions.size(),
                     [&](std::size_t v) { return mesh.worldPosition(static_cast<std::uint32_t>(v)); });
}

INSTANTIATE_TEST_SUITE_P(AllEncodings, NodeDataTest,
                         testing::Values("node_xy_v22_ascii.msh", "node_xy_v22_bin.msh",
                                         "node_xy_v41_ascii.msh", "node_xy_v41_bin.msh"));

// $ElementData: gmsh's ModifyComponents evaluates x + 2 y of an element at its last node (seen in
// the files: element 17 = nodes 1 5 16 gets the value at node 16), so each face, kept in the file's
// winding, must carry x + 2 y of its third corner.
class ElementDataTest : public testing::TestWithParam<const char*> {};

TEST_P(ElementDataTest, EveryFaceGetsItsElementsValue) {
  const Mesh mesh = readMsh(fieldFixture(GetParam()));
  ASSERT_EQ(mesh.faceCount(), 32u);
  expectXPlus2YField(mesh, true, mesh.faceCount(),
                     [&](std::size_t f) { return mesh.worldPosition(mesh.faces[f].vertex[2]); });
}

INSTANTIATE_TEST_SUITE_P(AllEncodings, ElementDataTest,
                         testing::Values("element_xy_v22_ascii.msh", "element_xy_v22_bin.msh",
                                         "element_xy_v41_ascii.msh", "element_xy_v41_bin.msh"));

// A volume-only tet10 cube: the rendered faces are the tetrahedra's skin faces, each split into four
// triangles. Every one carries a value, the four pieces of one skin face the same one (their
// tetrahedron's), and the values are x + 2 y at a node of the cube (gmsh's last node of the tet).
TEST(ElementDataTest, SkinAndSplitFacesGetTheirTetrahedronsValue) {
  const Mesh mesh = readMsh(fieldFixture("element_tet10_v41_bin.msh"));
  ASSERT_EQ(mesh.fields.size(), 1u);
  const MeshField& field = mesh.fields[0];
  ASSERT_EQ(field.at, FieldAt::kElement);
  ASSERT_EQ(field.itemCount(), mesh.faceCount());
  ASSERT_EQ(mesh.source.skinFaces * 4, mesh.faceCount());
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    ASSERT_FALSE(std::isnan(field.scalar(f))) << f;
    EXPECT_EQ(field.scalar(f), field.scalar(f - f % 4)) << f;
    EXPECT_GE(field.scalar(f), 0.0f);
    EXPECT_LE(field.scalar(f), 3.0f);
  }
  // Not one element's value everywhere: the skin faces come from many tetrahedra.
  std::set<float> distinct(field.values.begin(), field.values.end());
  EXPECT_GE(distinct.size(), 10u);
}

// 8-node quads: lancer splits each into four quads around a centre node it adds, whose value must
// be the serendipity combination of the element's values (-1/4 of each corner, 1/2 of each mid-edge
// node), as its position is. (gmsh's ModifyComponents leaves 0 at mid-edge nodes, so the values are
// not x + 2 y there: the oracle is the file's own values.) In each group of four faces the centre is
// on all four, mid-edge nodes on two, corners on one.
TEST(NodeDataTest, DerivedQuadCentresGetTheSerendipityValue) {
  const Mesh mesh = readMsh(fieldFixture("node_quad8_v41_ascii.msh"));
  ASSERT_EQ(mesh.fields.size(), 1u);
  const MeshField& field = mesh.fields[0];
  ASSERT_EQ(field.itemCount(), mesh.positions.size());
  EXPECT_EQ(mesh.positions.size(), 65u + 16u);  // 25 corners and 40 mid-edge nodes, 16 centres
  ASSERT_EQ(mesh.faceCount(), 64u);
  for (std::size_t group = 0; group < 16; ++group) {
    std::map<std::uint32_t, int> uses;
    for (std::size_t f = group * 4; f < group * 4 + 4; ++f)
      for (int c = 0; c < 4; ++c) ++uses[mesh.faces[f].vertex[c]];
    double expected = 0;
    std::uint32_t centre = kNoVertex;
    for (const auto& [vertex, count] : uses) {
      if (count == 4) centre = vertex;
      if (count == 1) expected -= 0.25 * field.scalar(vertex);
      if (count == 2) expected += 0.5 * field.scalar(vertex);
    }
    ASSERT_NE(centre, kNoVertex) << group;
    EXPECT_NEAR(field.scalar(centre), expected, 1e-5) << group;
    EXPECT_FALSE(std::isnan(field.scalar(centre)));
  }
}

// A 3-component $NodeData (x, 2 y, 2) in binary: each component lands on its vertex, and the
// scalar colour maps show is the magnitude.
TEST(NodeDataTest, VectorFieldComponentsAndMagnitude) {
  const Mesh mesh = readMsh(fieldFixture("node_vector_v41_bin.msh"));
  ASSERT_EQ(mesh.fields.size(), 1u);
  const MeshField& field = mesh.fields[0];
  ASSERT_EQ(field.components, 3);
  ASSERT_EQ(field.itemCount(), mesh.positions.size());
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(v);
    EXPECT_NEAR(field.values[v * 3 + 0], p.x, 1e-5);
    EXPECT_NEAR(field.values[v * 3 + 1], 2 * p.y, 1e-5);
    EXPECT_NEAR(field.values[v * 3 + 2], 2.0, 1e-6);
    EXPECT_NEAR(field.scalar(v), std::sqrt(p.x * p.x + 4 * p.y * p.y + 4), 1e-5);
  }
  EXPECT_NEAR(field.range().first, 2.0, 1e-5);
  EXPECT_NEAR(field.range().second, 3.0, 1e-5);
}

TEST(MeshFieldTest, VectorScalarIsTheLength) {
  MeshField field;
  field.components = 3;
  field.values = {3, 4, 0, 0, 0, -2};
  ASSERT_EQ(field.itemCount(), 2u);
  EXPECT_FLOAT_EQ(field.scalar(0), 5.0f);
  EXPECT_FLOAT_EQ(field.scalar(1), 2.0f);
}

TEST(MeshFieldTest, RangeIgnoresMissingValues) {
  MeshField field;
  field.values = {2, std::nanf(""), -1, 5};
  EXPECT_EQ(field.range(), (std::pair{-1.0f, 5.0f}));
  field.values = {std::nanf("")};
  EXPECT_EQ(field.range(), (std::pair{0.0f, 0.0f}));
}

TEST(MeshFieldTest, MeshesWithoutDataHaveNoFields) {
  const Mesh mesh = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/msh/square_tri3_v41_ascii.msh");
  EXPECT_TRUE(mesh.fields.empty());
}

}  // namespace
}  // namespace lancer
