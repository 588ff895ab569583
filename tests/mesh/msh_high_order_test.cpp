// Elements of order 3 and up: the split of complete triangles and quadrangles through all their
// nodes (checked on the node lattice for every order gmsh writes), and files gmsh wrote with
// -order 3 and 4 (tests/data/reader, scripts/make_reader_fixtures.sh): the unit square keeps its
// area and stays one consistently wound sheet; volumes give their closed skin through their corners.
#include <gtest/gtest.h>

#include <bit>
#include <set>
#include <string>

#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh/high_order.hpp"
#include "lancer/mesh/msh_reader.hpp"

namespace lancer {
namespace {

std::string readerFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/reader/" + name;
}

TEST(MshHighOrder, CompleteElementsAreSplitIntoOrderSquaredFacesUsingEveryNode) {
  for (const int type : {21, 23, 25, 42, 43, 44, 45, 46, 36, 37, 38, 47, 48, 49, 50, 51}) {
    SCOPED_TRACE(type);
    const int p = mshCompleteSurfaceOrder(type);
    const int corners = mshSurfaceCorners(type);
    const std::vector<MshSubFace>& faces = mshHighOrderSurfaceFaces(type);
    ASSERT_EQ(faces.size(), static_cast<std::size_t>(p * p));
    std::set<int> used;
    int boundaryEdges = 0;
    for (const MshSubFace& face : faces) {
      EXPECT_EQ(face.corner[3] == kNoSubCorner, corners == 3);
      for (int c = 0; c < corners; ++c) used.insert(face.corner[c]);
      boundaryEdges += std::popcount(face.edgeMask);
    }
    EXPECT_EQ(used.size(), static_cast<std::size_t>(mshElementType(type).nodeCount));
    EXPECT_EQ(*used.rbegin(), mshElementType(type).nodeCount - 1);
    EXPECT_EQ(boundaryEdges, corners * p);  // each element edge in p pieces
  }
  // Incomplete (serendipity) elements and the 4-node "MINI" triangle: drawn through their corners.
  for (const int type : {20, 22, 24, 39, 40, 41, 138}) {
    SCOPED_TRACE(type);
    ASSERT_EQ(mshHighOrderSurfaceFaces(type).size(), 1u);
    EXPECT_EQ(mshHighOrderSurfaceFaces(type)[0].corner[0], 0);
  }
  EXPECT_TRUE(mshHighOrderSurfaceFaces(29).empty());  // a volume
}

TEST(MshHighOrder, CubicQuadsAndQuarticTrianglesCoverTheSquareAsOneSheet) {
  struct Case {
    const char* file;
    std::size_t faces;
    std::size_t nodes;
  };
  // gmsh -order 3 of square.geo's 16 quads: 16 nodes each, 9 quads; -order 4 of its 32 triangles:
  // 15 nodes each, 16 triangles (MSH 2 binary, each element twice: two physical groups).
  for (const Case& c : {Case{"square_quad16_v41_ascii.msh", 16 * 9, 13 * 13},
                        Case{"square_tri15_v22_bin.msh", 32 * 16, 17 * 17}}) {
    SCOPED_TRACE(c.file);
    const Mesh mesh = readMsh(readerFixture(c.file));
    EXPECT_EQ(mesh.faceCount(), c.faces);
    EXPECT_EQ(mesh.positions.size(), c.nodes);
    EXPECT_TRUE(mesh.source.unrenderableByType.empty());
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_NEAR(stats.area, 1.0, 1e-12);
    ASSERT_EQ(stats.shells.size(), 1u);
    EXPECT_FALSE(stats.shells[0].closed);
    EXPECT_TRUE(stats.shells[0].consistentlyOriented);
  }
}

TEST(MshHighOrder, VolumesOfOrderThreeGiveTheirClosedSkinThroughTheirCorners) {
  for (const char* file :
       {"cube_tet20_v41_bin.msh", "cube_tet20_v22_ascii.msh", "cube_hex64_v41_ascii.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(readerFixture(file));
    EXPECT_GT(mesh.faceCount(), 0u);
    EXPECT_TRUE(mesh.source.unrenderableByType.empty());
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_NEAR(stats.area, 6.0, 1e-9);  // the unit cube: flat faces, so corners are exact
    ASSERT_EQ(stats.shells.size(), 1u);
    EXPECT_TRUE(stats.shells[0].closed);
    EXPECT_TRUE(stats.shells[0].consistentlyOriented);
    EXPECT_NEAR(std::abs(stats.shells[0].signedVolume), 1.0, 1e-9);
  }
  EXPECT_EQ(mshElementRenderNote(29), "drawn through its corner nodes (its skin's faces are flat)");
  EXPECT_EQ(mshElementRenderNote(36), "split into flat faces through all its nodes");
  EXPECT_EQ(mshElementRenderNote(39),
            "drawn through its corner nodes (incomplete element: no interior nodes)");
  EXPECT_EQ(mshElementRenderNote(11), "");
}

}  // namespace
}  // namespace lancer
