#include "lancer/mesh/vertex_normals.hpp"
#include "lancer/mesh/face_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lancer {
namespace {

// A unit cube of 6 quads, outward winding, all in physical group 0.
struct Cube {
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;
  std::vector<std::int32_t> tags;
};

Cube unitCube() {
  Cube cube;
  for (int i = 0; i < 8; ++i)
    cube.positions.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) cube.faces.push_back({{q[0], q[1], q[2], q[3]}});
  cube.tags.assign(cube.faces.size(), 0);
  return cube;
}

TEST(VertexNormals, CubeKeepsSharpEdgesBelowCreaseAngle) {
  const Cube cube = unitCube();
  const CornerNormals normals = computeCornerNormals(cube.positions, cube.faces, cube.tags, 60.0f);
  for (std::size_t f = 0; f < cube.faces.size(); ++f) {
    const Vec3 n = faceNormal(cube.positions, cube.faces[f]);
    for (int c = 0; c < 4; ++c) {
      const Vec3 corner = normals.normals[normals.faceCorner[f][c]];
      EXPECT_NEAR(dot(corner, n), 1.0f, 1e-6f);
    }
  }
  EXPECT_EQ(normals.normals.size(), 24u);  // 8 corners x 3 faces each
}

TEST(VertexNormals, CubeSmoothedAboveCreaseAngle) {
  const Cube cube = unitCube();
  const CornerNormals normals = computeCornerNormals(cube.positions, cube.faces, cube.tags, 95.0f);
  // Each cube corner gets the diagonal direction, shared by its three faces.
  EXPECT_EQ(normals.normals.size(), 8u);
  const Vec3 corner7 = normals.normals[normals.faceCorner[1][2]];  // vertex 7 = (1,1,1)
  EXPECT_NEAR(dot(corner7, normalize(Vec3{1, 1, 1})), 1.0f, 1e-6f);
}

TEST(VertexNormals, PhysicalGroupBoundaryStaysSharp) {
  // Two coplanar-ish triangles folded by 10 degrees, in different physical groups.
  const float fold = 10.0f * 3.14159265f / 180.0f;
  std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-std::cos(fold), 0, std::sin(fold)}};
  std::vector<MeshFace> faces = {{{0, 1, 2, kNoVertex}}, {{0, 2, 3, kNoVertex}}};
  const CornerNormals same = computeCornerNormals(positions, faces, std::vector<std::int32_t>{1, 1}, 60.0f);
  EXPECT_EQ(same.faceCorner[0][0], same.faceCorner[1][0]);  // smoothed across the fold
  const CornerNormals split = computeCornerNormals(positions, faces, std::vector<std::int32_t>{1, 2}, 60.0f);
  EXPECT_NE(split.faceCorner[0][0], split.faceCorner[1][0]);
  EXPECT_NEAR(dot(split.normals[split.faceCorner[0][0]], Vec3{0, 0, 1}), 1.0f, 1e-6f);
}

// A grid of 40k vertices (several chunks of vertices), a gentle wave, its left and right halves in
// two groups: the border's vertices are walked in every chunk, and their corners must index their
// own vertex's normals (which lie in vertex order), one per side of the border.
TEST(VertexNormals, WalkedCornersOfEveryChunkIndexTheirOwnVertexsNormals) {
  constexpr int n = 200;
  std::vector<Vec3> positions;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = float(i) / n, y = float(j) / n;
      positions.push_back({x, y, 0.02f * std::sin(6.0f * x) * std::cos(4.0f * y)});
    }
  auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  std::vector<MeshFace> faces;
  std::vector<std::int32_t> tags;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      faces.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
      tags.push_back(2 * i < n ? 1 : 2);
    }
  for (const int threads : {1, 2}) {
    const CornerNormals normals = computeCornerNormals(positions, faces, tags, 30.0f, threads);
    std::vector<std::uint32_t> low(positions.size(), std::numeric_limits<std::uint32_t>::max());
    std::vector<std::uint32_t> high(positions.size(), 0);
    // Per vertex, the index its corners of group 1 and of group 2 take (one each).
    std::vector<std::array<std::uint32_t, 2>> byGroup(positions.size(), {kNoVertex, kNoVertex});
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int c = 0; c < 4; ++c) {
        const std::uint32_t v = faces[f].vertex[c], index = normals.faceCorner[f][c];
        ASSERT_LT(index, normals.normals.size());
        low[v] = std::min(low[v], index);
        high[v] = std::max(high[v], index);
        std::uint32_t& side = byGroup[v][tags[f] - 1];
        if (side == kNoVertex) side = index;
        EXPECT_EQ(side, index) << "vertex " << v << ", " << threads << " threads";
        // The corner's normal is its face's, give or take the wave's few degrees.
        EXPECT_GT(dot(normals.normals[index], faceNormal(positions, faces[f])), 0.99f);
      }
    for (std::size_t v = 0; v + 1 < positions.size(); ++v)
      ASSERT_LT(high[v], low[v + 1]) << "vertex " << v << ", " << threads << " threads";
    for (int j = 0; j <= n; ++j)  // the border, x = 0.5: one normal per side
      EXPECT_NE(byGroup[at(n / 2, j)][0], byGroup[at(n / 2, j)][1]) << "row " << j;
    EXPECT_EQ(normals.normals.size(), positions.size() + (n + 1));
  }
}

}  // namespace
}  // namespace lancer
