// Arrows along a vector field: node data placed one per occupied cell of a grid over the surface
// (not one per node), at most max_count; element data at each element's centroid; built as closed
// triangle meshes of known size and length; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

// A side x side grid of quads over the unit square (z = 0) carrying the vector field `vector(p)`.
template <class Field>
Mesh gridMesh(int side, Field vector) {
  Mesh mesh;
  for (int j = 0; j <= side; ++j)
    for (int i = 0; i <= side; ++i) mesh.positions.push_back({float(i) / side, float(j) / side, 0});
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const auto v = static_cast<std::uint32_t>(j * (side + 1) + i);
      mesh.faces.push_back(MeshFace{
          {v, v + 1, v + 2 + static_cast<std::uint32_t>(side), v + 1 + static_cast<std::uint32_t>(side)}});
    }
  MeshField field;
  field.name = "velocity";
  field.components = 3;
  for (const Vec3& p : mesh.positions) {
    const Vec3 v = vector(p);
    field.values.insert(field.values.end(), {v.x, v.y, v.z});
  }
  mesh.fields.push_back(field);
  return mesh;
}

TEST(Arrows, PlacedOnAGridNotPerNode) {
  const Mesh mesh = gridMesh(60, [](const Vec3&) { return Vec3{1, 0, 0}; });
  for (const int maxCount : {1, 10, 100, 500}) {
    const ArrowPlacement placement = placeArrows(mesh, mesh.fields[0], maxCount);
    EXPECT_LE(static_cast<int>(placement.vertices.size()), maxCount);
    // A grid about as fine as the count allows: at least a third of it is used.
    EXPECT_GE(static_cast<int>(placement.vertices.size()), std::max(1, maxCount / 3)) << maxCount;
    // One arrow per cell: no two in one cell, so none closer than a cell apart along both axes.
    std::set<std::pair<int, int>> cells;
    for (const std::uint32_t v : placement.vertices) {
      const Vec3 p = mesh.positions[v];
      EXPECT_TRUE(
          cells.insert({int(std::floor(p.x / placement.cellSize)), int(std::floor(p.y / placement.cellSize))})
              .second);
    }
  }
  // 3721 nodes, 100 arrows: far fewer than one per node.
  EXPECT_EQ(placeArrows(mesh, mesh.fields[0], 100).vertices.size() < 200, true);
}

TEST(Arrows, ClosedMeshesAlongTheVectorsWithLengthByMagnitudeOrFixed) {
  // v = (x, 0, 0): arrows point along +x, the longest 0.9 cells long; x = 0 has no arrow.
  const Mesh mesh = gridMesh(40, [](const Vec3& p) { return Vec3{p.x, 0, 0}; });
  ArrowSpec spec;
  spec.field = "velocity";
  spec.maxCount = 50;
  const ArrowPlacement placement = placeArrows(mesh, mesh.fields[0], 50);
  const Mesh arrows = arrowMesh(spec, mesh);
  const std::size_t count = arrows.faces.size() / (6 * kArrowSides);
  EXPECT_EQ(arrows.faces.size(), count * 6 * kArrowSides);
  EXPECT_EQ(count, placement.vertices.size());
  ASSERT_EQ(arrows.fields.size(), 1u);
  EXPECT_EQ(arrows.fields[0].name, "velocity magnitude");
  EXPECT_EQ(arrows.fields[0].itemCount(), arrows.positions.size());
  // Every edge of the arrows is shared by exactly two triangles: closed shells.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const MeshFace& f : arrows.faces)
    for (int c = 0; c < 3; ++c) ++edges[std::minmax(f.vertex[c], f.vertex[(c + 1) % 3])];
  for (const auto& [edge, uses] : edges) EXPECT_EQ(uses, 2);
  // The longest arrow reaches 0.9 cells along +x from its base.
  float longest = 0;
  for (const Vec3& p : arrows.positions) longest = std::max(longest, p.x);
  EXPECT_NEAR(longest, 1.0 + 0.9 * placement.cellSize, 1e-4);
  // Fixed length: every arrow 0.8 cells, tips at base + 0.8 cells.
  spec.fixedLength = true;
  const Mesh fixed = arrowMesh(spec, mesh);
  const int perArrow = 3 * kArrowSides + 2;
  for (std::size_t a = 0; a < fixed.positions.size() / perArrow; ++a) {
    const Vec3 base = fixed.positions[a * perArrow + 3 * kArrowSides],
               tip = fixed.positions[a * perArrow + 3 * kArrowSides + 1];
    EXPECT_NEAR(length(tip - base), 0.8 * placement.cellSize, 1e-5);
    EXPECT_NEAR(tip.y, base.y, 1e-6);
  }
}

TEST(Arrows, AddedToTheSceneAsGeometry) {
  const std::string text = R"(
[[mesh]]
file = "../fields/node_vector_v41_bin.msh"
arrows = { field = "temperature", max_count = 8, color = [1, 0, 0] }
)";
  const SceneDescription description = parseScene(text, test::dataFile("render/arrows.toml"));
  const Scene scene = buildScene(description);
  const Mesh mesh = readMsh(test::dataFile("fields/node_vector_v41_bin.msh"));
  const std::size_t arrowFaces = scene.geometry.faces.size() - mesh.faces.size();
  EXPECT_GT(arrowFaces, 0u);
  EXPECT_LE(arrowFaces, 8u * 6 * kArrowSides);
  EXPECT_EQ(arrowFaces % (6 * kArrowSides), 0u);
  EXPECT_EQ(scene.appearance.materials.back().kd, (Vec3{1, 0, 0}));
}

// The base and the tip of each arrow of an arrow mesh (appendArrow's last two vertices).
std::vector<std::pair<Vec3d, Vec3d>> arrowBasesAndTips(const Mesh& arrows) {
  const int perArrow = 3 * kArrowSides + 2;
  std::vector<std::pair<Vec3d, Vec3d>> out;
  for (std::size_t a = 0; a < arrows.positions.size() / perArrow; ++a)
    out.emplace_back(arrows.worldPosition(static_cast<std::uint32_t>(a * perArrow + 3 * kArrowSides)),
                     arrows.worldPosition(static_cast<std::uint32_t>(a * perArrow + 3 * kArrowSides + 1)));
  return out;
}

TEST(Arrows, ElementDataStandsAtEachElementsCentroid) {
  // gmsh's (x, 2 y, 2) per triangle: one arrow per triangle, at its centroid, along its value.
  const Mesh mesh = readMsh(test::dataFile("fields/element_vector_v41_bin.msh"));
  ASSERT_EQ(mesh.fields.at(0).at, FieldAt::kElement);
  ArrowSpec spec;
  spec.field = "temperature";
  const auto arrows = arrowBasesAndTips(arrowMesh(spec, mesh));
  ASSERT_EQ(arrows.size(), mesh.faces.size());
  std::set<std::uint32_t> faces;
  for (const auto& [base, tip] : arrows) {
    std::uint32_t found = kNoVertex;
    for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
      Vec3d centroid{0, 0, 0};
      for (int c = 0; c < 3; ++c)
        centroid = centroid + mesh.worldPosition(mesh.faces[f].vertex[c]) * (1.0 / 3);
      if (length(centroid - base) < 1e-6) found = f;
    }
    ASSERT_NE(found, kNoVertex) << "an arrow stands at no triangle's centroid";
    faces.insert(found);
    const float* value = &mesh.fields[0].values[found * 3];
    const Vec3d expected = normalize(Vec3d{value[0], value[1], value[2]});
    EXPECT_NEAR(dot(normalize(tip - base), expected), 1.0, 1e-5);
  }
  EXPECT_EQ(faces.size(), mesh.faces.size());
}

TEST(Arrows, ElementDataOnSecondOrderSkinsGivesOneArrowPerElementFace) {
  // 10-node tetrahedra: each skin face is drawn as four triangles, and carries one arrow.
  const Mesh mesh = readMsh(test::dataFile("fields/element_vector_tet10_v41_bin.msh"));
  ASSERT_EQ(mesh.source.skinFaces * 4, mesh.faces.size());
  ArrowSpec spec;
  spec.field = "temperature";
  const auto arrows = arrowBasesAndTips(arrowMesh(spec, mesh));
  EXPECT_EQ(arrows.size(), mesh.source.skinFaces);
  // Each on the cube's surface, at the centroid of a skin face (not at a corner of its four parts).
  for (const auto& [base, tip] : arrows) {
    const double toSurface = std::min({base.x, base.y, base.z, 1 - base.x, 1 - base.y, 1 - base.z});
    EXPECT_NEAR(toSurface, 0.0, 1e-6);
  }
  // Beyond max_count, the grid thins them as it thins node arrows.
  spec.maxCount = 10;
  EXPECT_LE(arrowBasesAndTips(arrowMesh(spec, mesh)).size(), 10u);
}

TEST(ArrowsBadInput, ScalarFieldsCountsAndScale) {
  const std::string scalar = R"(
[[mesh]]
file = "../fields/node_xy_v41_bin.msh"
arrows = { field = "temperature" }
)";
  const SceneDescription description = parseScene(scalar, test::dataFile("render/arrows.toml"));
  const std::string message = test::messageOf([&] { buildScene(description); });
  EXPECT_NE(
      message.find(
          "arrows.toml:4:10: error: arrows field \"temperature\" must be a vector of 3 components (node, "
          "element or element-node data), but it is node data of 1 component"),
      std::string::npos)
      << message;
  const std::string elementScalar = R"(
[[mesh]]
file = "../fields/element_xy_v41_bin.msh"
arrows = { field = "temperature" }
)";
  const SceneDescription elements = parseScene(elementScalar, test::dataFile("render/arrows.toml"));
  EXPECT_NE(test::messageOf([&] { buildScene(elements); })
                .find("must be a vector of 3 components (node, element or element-node data), but it is "
                      "element data of 1 component"),
            std::string::npos);
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\narrows = { field = \"v\", max_count = 0 }\n",
                                 "mesh[0].arrows.max_count");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\narrows = { field = \"v\", max_count = 10000000 }\n",
      "mesh[0].arrows.max_count");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\narrows = { field = \"v\", scale = \"big\" }\n",
                                 "must be \"auto\" or a number > 0");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\narrows = { field = \"v\", scale = -1 }\n",
                                 "mesh[0].arrows.scale");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\narrows = { field = \"v\", length = \"long\" }\n", "fixed");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\narrows = { max_count = 3 }\n", "field");
}

}  // namespace
}  // namespace lancer
