// Shells, closedness and orientation on hand-built cubes, where the right answer is obvious.
#include "lancer/mesh/mesh_stats.hpp"

#include <gtest/gtest.h>

namespace lancer {
namespace {

// A unit cube of 6 outward quads at `offset`, appended to mesh.
void addCube(Mesh& mesh, Vec3 offset) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (int i = 0; i < 8; ++i)
    mesh.positions.push_back(Vec3{float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)} + offset);
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.faces.push_back({{base + q[0], base + q[1], base + q[2], base + q[3]}});
    mesh.facePhysicalTag.push_back(7);
    mesh.faceEntityTag.push_back(1);
    mesh.faceEdgeMask.push_back(kAllEdges);
  }
}

TEST(MeshStats, ClosedOutwardCube) {
  Mesh mesh;
  mesh.origin = {100, 0, 0};
  addCube(mesh, {0, 0, 0});
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_DOUBLE_EQ(stats.area, 6.0);
  EXPECT_EQ(stats.quads, 6u);
  EXPECT_EQ(stats.facesByPhysicalTag.at(7), 6u);
  EXPECT_EQ(stats.worldBounds.lower.x, 100.0);
  EXPECT_EQ(stats.worldBounds.upper.z, 1.0);
  ASSERT_EQ(stats.shells.size(), 1u);
  EXPECT_TRUE(stats.shells[0].closed);
  EXPECT_TRUE(stats.shells[0].consistentlyOriented);
  EXPECT_DOUBLE_EQ(stats.shells[0].signedVolume, 1.0);
}

TEST(MeshStats, FlippedFaceBreaksOrientation) {
  Mesh mesh;
  addCube(mesh, {0, 0, 0});
  std::swap(mesh.faces[2].vertex[1], mesh.faces[2].vertex[3]);
  const MeshStats stats = computeMeshStats(mesh);
  ASSERT_EQ(stats.shells.size(), 1u);
  EXPECT_TRUE(stats.shells[0].closed);
  EXPECT_FALSE(stats.shells[0].consistentlyOriented);
}

TEST(MeshStats, InwardCubeHasNegativeVolume) {
  Mesh mesh;
  addCube(mesh, {0, 0, 0});
  for (MeshFace& face : mesh.faces) std::swap(face.vertex[1], face.vertex[3]);
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_TRUE(stats.shells[0].consistentlyOriented);
  EXPECT_DOUBLE_EQ(stats.shells[0].signedVolume, -1.0);
}

TEST(MeshStats, OpenBoxAndSeparateShells) {
  Mesh mesh;
  addCube(mesh, {0, 0, 0});
  addCube(mesh, {3, 0, 0});
  mesh.faces.pop_back();  // the second cube loses a side
  mesh.facePhysicalTag.pop_back();
  mesh.faceEntityTag.pop_back();
  mesh.faceEdgeMask.pop_back();
  const MeshStats stats = computeMeshStats(mesh);
  ASSERT_EQ(stats.shells.size(), 2u);
  EXPECT_EQ(stats.shells[0].faceCount, 6u);
  EXPECT_TRUE(stats.shells[0].closed);
  EXPECT_EQ(stats.shells[1].faceCount, 5u);
  EXPECT_FALSE(stats.shells[1].closed);
  EXPECT_TRUE(stats.shells[1].consistentlyOriented);
}

TEST(MeshStats, NonManifoldEdgeIsNeitherClosedNorOriented) {
  // Three triangles on one edge.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  for (std::uint32_t apex : {2u, 3u, 4u}) {
    mesh.faces.push_back({{0, 1, apex, kNoVertex}});
    mesh.facePhysicalTag.push_back(0);
    mesh.faceEntityTag.push_back(0);
    mesh.faceEdgeMask.push_back(0b111);
  }
  const MeshStats stats = computeMeshStats(mesh);
  ASSERT_EQ(stats.shells.size(), 1u);
  EXPECT_FALSE(stats.shells[0].closed);
  EXPECT_FALSE(stats.shells[0].consistentlyOriented);
}

}  // namespace
}  // namespace lancer
