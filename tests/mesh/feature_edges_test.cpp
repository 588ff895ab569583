// Feature edges on gmsh meshes: a cube's skin keeps exactly its 12 edges, a flat quad plate only its
// border, and a group boundary counts as a feature.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/feature_edges.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// Number of coordinates of p that sit on the box's faces.
int coordinatesOnBox(const Vec3& p, const Aabb& box) {
  int count = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const float v = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
    const float lo = axis == 0 ? box.lower.x : axis == 1 ? box.lower.y : box.lower.z;
    const float hi = axis == 0 ? box.upper.x : axis == 1 ? box.upper.y : box.upper.z;
    if (std::abs(v - lo) < 1e-5f || std::abs(v - hi) < 1e-5f) ++count;
  }
  return count;
}

TEST(FeatureEdges, CubeSkinKeepsExactlyItsTwelveEdges) {
  const Mesh mesh = readMsh(test::mshFixture("cube_tet4_v41_ascii.msh"));
  const Aabb box = faceBounds(mesh);
  const std::vector<std::uint8_t> masks = featureEdgeMasks(mesh, 30.0f);
  ASSERT_EQ(masks.size(), mesh.faces.size());
  int marked = 0;
  double markedLength = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const MeshFace& face = mesh.faces[f];
    for (int i = 0; i < 3; ++i) {
      const Vec3& a = mesh.positions[face.vertex[i]];
      const Vec3& b = mesh.positions[face.vertex[(i + 1) % 3]];
      const bool onCubeEdge = coordinatesOnBox(a, box) >= 2 && coordinatesOnBox(b, box) >= 2 &&
                              coordinatesOnBox((a + b) * 0.5f, box) >= 2;
      const bool isMarked = masks[f] & (1u << i);
      EXPECT_EQ(isMarked, onCubeEdge) << "face " << f << " edge " << i;
      if (isMarked) {
        ++marked;
        markedLength += length(b - a);
      }
    }
  }
  EXPECT_GT(marked, 0);
  EXPECT_NEAR(markedLength, 2 * 12 * 1.0, 1e-4);  // 12 unit edges, each seen from both faces
}

TEST(FeatureEdges, FlatPlateOfQuadsKeepsOnlyItsBorder) {
  const Mesh mesh = readMsh(test::mshFixture("square_quad4_v41_ascii.msh"));
  const Aabb box = faceBounds(mesh);
  const std::vector<std::uint8_t> masks = featureEdgeMasks(mesh, 30.0f);
  double borderLength = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int i = 0; i < 4; ++i) {
      if (!(masks[f] & (1u << i))) continue;
      const Vec3& a = mesh.positions[mesh.faces[f].vertex[i]];
      const Vec3& b = mesh.positions[mesh.faces[f].vertex[(i + 1) % 4]];
      // z is flat, so a border point has z plus one of x, y on the box.
      EXPECT_GE(coordinatesOnBox((a + b) * 0.5f, box), 2);
      borderLength += length(b - a);
    }
  }
  EXPECT_NEAR(borderLength, 4.0, 1e-4);
}

TEST(FeatureEdges, GroupBoundaryAndCreaseAngle) {
  // Two triangles sharing edge (1,2), folded by about 19 degrees: a crease for 10, not for 30, and a
  // feature at any angle once they belong to different physical groups.
  Mesh mesh;
  const float fold = 20.0f * 3.14159265f / 180.0f;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.positions[3] = {1, 1, std::sin(fold) * 0.7071f};
  mesh.faces = {MeshFace{{0, 1, 2, kNoVertex}}, MeshFace{{1, 3, 2, kNoVertex}}};
  mesh.facePhysicalTag = {1, 1};
  mesh.faceEntityTag = {1, 1};
  mesh.faceEdgeMask = {kAllEdges, kAllEdges};
  EXPECT_EQ(featureEdgeMasks(mesh, 30.0f)[0], 0b101);  // edges 0 and 2 are the border; 1 is shared
  EXPECT_EQ(featureEdgeMasks(mesh, 10.0f)[0], 0b111);
  mesh.facePhysicalTag = {1, 2};
  EXPECT_EQ(featureEdgeMasks(mesh, 30.0f)[0], 0b111);
  // An edge that is not an element edge (cleared mask) is never drawn.
  mesh.faceEdgeMask = {0b110, kAllEdges};
  EXPECT_EQ(featureEdgeMasks(mesh, 10.0f)[0], 0b110);
}

}  // namespace
}  // namespace lancer
