// The normals of a deformed step computed again in place (updateCornerNormals) are the bits a full
// computation gives, as long as no vertex changes how it is smoothed; a new crease or a collapsed
// face says no. Meshes large enough for several chunks and vertex ranges, placed after another
// mesh's vertices and normals as in a scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/vertex_normals.hpp"

namespace lancer {
namespace {

// An n x n grid of quads over [0, 1]^2, every third row of cells split into two triangles; the
// left half in group 1, the right in group 2 (a group border along x = 0.5).
struct Grid {
  int n = 0;
  std::vector<Vec3> flat;
  std::vector<MeshFace> faces;
  std::vector<std::int32_t> tags;
};

Grid grid(int n) {
  Grid g;
  g.n = n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.flat.push_back({float(i) / n, float(j) / n, 0.0f});
  auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t tag = 2 * i < n ? 1 : 2;
      if (j % 3 == 0) {
        g.faces.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), kNoVertex}});
        g.faces.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1), kNoVertex}});
        g.tags.insert(g.tags.end(), {tag, tag});
      } else {
        g.faces.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}});
        g.tags.push_back(tag);
      }
    }
  return g;
}

// The grid bent into a wave of amplitude `a` (smooth: neighbouring faces turn by a few degrees),
// and, with `foldAt`, folded sharply along x = foldAt.
std::vector<Vec3> deformed(const Grid& g, float a, float foldAt = -1) {
  std::vector<Vec3> p = g.flat;
  for (Vec3& v : p) {
    v.z = a * std::sin(6.0f * v.x) * std::cos(4.0f * v.y);
    if (foldAt >= 0 && v.x > foldAt) v.z += 2.0f * (v.x - foldAt);  // a 63-degree crease
  }
  return p;
}

bool sameBits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// The grid placed as a scene's second mesh: after 5 vertices and 7 normals of another.
struct Placed {
  std::vector<Vec3> positions;
  std::vector<MeshFace> faces;
  CornerNormals normals;
  std::vector<Vec3> faceNormals;
  static constexpr std::uint32_t kVertexBase = 5, kNormalBase = 7;
};

Placed place(const Grid& g, const std::vector<Vec3>& positions, const CornerNormals& normals) {
  Placed placed;
  placed.positions.assign(Placed::kVertexBase, Vec3{9, 9, 9});
  placed.positions.insert(placed.positions.end(), positions.begin(), positions.end());
  placed.faces = g.faces;
  placed.normals.normals.assign(Placed::kNormalBase, Vec3{0, 0, 1});
  placed.normals.normals.insert(placed.normals.normals.end(), normals.normals.begin(), normals.normals.end());
  placed.normals.faceCorner = normals.faceCorner;
  for (std::size_t f = 0; f < g.faces.size(); ++f)
    for (int c = 0; c < g.faces[f].cornerCount(); ++c) {
      placed.faces[f].vertex[c] += Placed::kVertexBase;
      placed.normals.faceCorner[f][c] += Placed::kNormalBase;
    }
  placed.faceNormals.assign(g.faces.size(), Vec3{});
  return placed;
}

NormalsUpdate update(Placed& placed, const Grid& g, const std::vector<Vec3>& positions,
                     const CornerNormalWalks& walks, float crease, int threads) {
  std::copy(positions.begin(), positions.end(), placed.positions.begin() + Placed::kVertexBase);
  return updateCornerNormals(
      placed.positions,
      CornerNormalsSpan{placed.faces, Placed::kVertexBase, g.flat.size(), Placed::kNormalBase}, g.tags,
      crease, walks, threads, std::span<Vec3>(placed.normals.normals).subspan(Placed::kNormalBase),
      placed.normals.faceCorner, placed.faceNormals);
}

TEST(CornerNormalsUpdate, ADeformedStepGetsTheBitsOfAFullComputation) {
  const Grid g = grid(220);  // 48k vertices: several chunks and vertex ranges
  const std::vector<Vec3> first = deformed(g, 0.02f), next = deformed(g, 0.05f);
  for (const int threads : {1, 2, 3}) {
    CornerNormalWalks walks;
    const CornerNormals before =
        computeCornerNormals(first, g.faces, g.tags, 30.0f, threads, nullptr, &walks);
    // The group border's vertices are walked (their corners take one normal per side).
    ASSERT_GE(walks.vertex.size(), static_cast<std::size_t>(g.n));
    Placed placed = place(g, first, before);
    ASSERT_EQ(update(placed, g, next, walks, 30.0f, threads), NormalsUpdate::Updated)
        << threads << " threads";
    std::vector<Vec3> faceNormals;
    const CornerNormals expected = computeCornerNormals(next, g.faces, g.tags, 30.0f, threads, &faceNormals);
    std::vector<Vec3> updated(placed.normals.normals.begin() + Placed::kNormalBase,
                              placed.normals.normals.end());
    EXPECT_TRUE(sameBits(updated, expected.normals)) << threads << " threads";
    EXPECT_TRUE(sameBits(placed.faceNormals, faceNormals)) << threads << " threads";
    EXPECT_FALSE(sameBits(expected.normals, before.normals));  // the step did move them
    for (std::size_t k = 0; k < Placed::kNormalBase; ++k)
      EXPECT_EQ(placed.normals.normals[k], (Vec3{0, 0, 1}));
  }
}

TEST(CornerNormalsUpdate, ACubeWhoseEveryCornerIsACreaseFollowsAStretch) {
  std::vector<Vec3> positions;
  for (int i = 0; i < 8; ++i) positions.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
  const std::vector<MeshFace> faces = {{{0, 2, 3, 1}}, {{4, 5, 7, 6}}, {{0, 1, 5, 4}},
                                       {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}};
  const std::vector<std::int32_t> tags(6, 0);
  CornerNormalWalks walks;
  CornerNormals normals = computeCornerNormals(positions, faces, tags, 60.0f, 1, nullptr, &walks);
  EXPECT_EQ(walks.vertex.size(), 8u);
  for (Vec3& p : positions) p = Vec3{1.5f * p.x + 0.25f * p.y, p.y, 0.8f * p.z};  // a shear: still 24 normals
  std::vector<Vec3> faceNormals(6);
  ASSERT_EQ(updateCornerNormals(positions, CornerNormalsSpan{faces, 0, 8, 0}, tags, 60.0f, walks, 1,
                                normals.normals, normals.faceCorner, faceNormals),
            NormalsUpdate::Updated);
  std::vector<Vec3> expectedFaceNormals;
  const CornerNormals expected = computeCornerNormals(positions, faces, tags, 60.0f, 1, &expectedFaceNormals);
  EXPECT_TRUE(sameBits(normals.normals, expected.normals));
  EXPECT_TRUE(sameBits(faceNormals, expectedFaceNormals));
}

TEST(CornerNormalsUpdate, ANewCreaseOrACollapsedFaceSaysWhy) {
  const Grid g = grid(60);
  const std::vector<Vec3> first = deformed(g, 0.01f);
  CornerNormalWalks walks;
  const CornerNormals before = computeCornerNormals(first, g.faces, g.tags, 30.0f, 2, nullptr, &walks);
  Placed folded = place(g, first, before);
  EXPECT_EQ(update(folded, g, deformed(g, 0.01f, 0.3f), walks, 30.0f, 2),  // a crease inside group 1
            NormalsUpdate::SmoothingChanged);
  std::vector<Vec3> collapsed = first;
  collapsed[g.faces[100].vertex[1]] = collapsed[g.faces[100].vertex[0]];  // a quad loses an edge...
  collapsed[g.faces[100].vertex[2]] = collapsed[g.faces[100].vertex[0]];  // ...and its area
  Placed flat = place(g, first, before);
  EXPECT_EQ(update(flat, g, collapsed, walks, 30.0f, 2), NormalsUpdate::FaceDegenerate);
  Placed same = place(g, first, before);
  EXPECT_EQ(update(same, g, first, walks, 30.0f, 2), NormalsUpdate::Updated);
}

}  // namespace
}  // namespace lancer
