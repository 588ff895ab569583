// The reader against gmsh-made fixtures (tests/data/geo/*.geo -> scripts/make_fixtures.sh): counts,
// bounding boxes and areas known from the geometry, for every format, encoding and element type.
#include "lancer/mesh/msh_reader.hpp"

#include <gtest/gtest.h>

#include <bit>

#include <cmath>
#include <numbers>
#include <set>

#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh/node_table.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::mshFixture;

struct FixtureCase {
  const char* file;
  const char* version;
  bool binary;
  std::uint64_t triangles;
  std::uint64_t quads;
  double area;
  Vec3d lower, upper;
  bool closed;
};

std::ostream& operator<<(std::ostream& out, const FixtureCase& c) { return out << c.file; }

class MshFixtureTest : public testing::TestWithParam<FixtureCase> {};

TEST_P(MshFixtureTest, CountsBoundsAndAreaMatchTheGeometry) {
  const FixtureCase& c = GetParam();
  const Mesh mesh = readMsh(mshFixture(c.file));
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_EQ(mesh.source.formatVersion, c.version);
  EXPECT_EQ(mesh.source.binary, c.binary);
  EXPECT_EQ(stats.triangles, c.triangles);
  EXPECT_EQ(stats.quads, c.quads);
  EXPECT_NEAR(stats.area, c.area, 1e-5 * c.area);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(stats.worldBounds.lower[axis], c.lower[axis], 1e-6);
    EXPECT_NEAR(stats.worldBounds.upper[axis], c.upper[axis], 1e-6);
  }
  ASSERT_EQ(stats.shells.size(), 1u);
  EXPECT_EQ(stats.shells[0].closed, c.closed);
  EXPECT_TRUE(stats.shells[0].consistentlyOriented);
  if (c.closed) {
    EXPECT_NEAR(stats.shells[0].signedVolume, 1.0, 1e-5);  // unit cube, normals outward
  }
  EXPECT_EQ(mesh.source.degenerateFacesDropped, 0u);
  EXPECT_EQ(mesh.faces.size(), mesh.facePhysicalTag.size());
  EXPECT_EQ(mesh.faces.size(), mesh.faceEntityTag.size());
  EXPECT_EQ(mesh.faces.size(), mesh.faceEdgeMask.size());
}

constexpr Vec3d kZero{0, 0, 0};
constexpr Vec3d kSquareTop{1, 1, 0};
constexpr Vec3d kCubeTop{1, 1, 1};

// The unit square is 4 x 4 cells: 32 triangles or 16 quads, four times that once second-order
// elements are split. The unit cube's skin has area 6 and encloses volume 1.
const FixtureCase kFixtures[] = {
    {"square_tri3_v22_ascii.msh", "2.2", false, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v22_bin.msh", "2.2", true, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v40_ascii.msh", "4.0", false, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v41_ascii.msh", "4.1", false, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v41_bin.msh", "4.1", true, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v41_ascii_crlf.msh", "4.1", false, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v22_ascii_crlf.msh", "2.2", false, 32, 0, 1, kZero, kSquareTop, false},
    {"square_tri3_v41_ascii_extras.msh", "4.1", false, 32, 0, 1, kZero, kSquareTop, false},
    {"nodedata_v41_bin.msh", "4.1", true, 32, 0, 1, kZero, kSquareTop, false},
    {"nodedata_v22_ascii.msh", "2.2", false, 32, 0, 1, kZero, kSquareTop, false},
    {"elementdata_v41_ascii.msh", "4.1", false, 32, 0, 1, kZero, kSquareTop, false},
    {"elementdata_v22_bin.msh", "2.2", true, 32, 0, 1, kZero, kSquareTop, false},
    {"square_quad4_v22_ascii.msh", "2.2", false, 0, 16, 1, kZero, kSquareTop, false},
    {"square_quad4_v22_bin.msh", "2.2", true, 0, 16, 1, kZero, kSquareTop, false},
    {"square_quad4_v40_ascii.msh", "4.0", false, 0, 16, 1, kZero, kSquareTop, false},
    {"square_quad4_v41_ascii.msh", "4.1", false, 0, 16, 1, kZero, kSquareTop, false},
    {"square_quad4_v41_bin.msh", "4.1", true, 0, 16, 1, kZero, kSquareTop, false},
    {"square_tri6_v22_ascii.msh", "2.2", false, 128, 0, 1, kZero, kSquareTop, false},
    {"square_tri6_v22_bin.msh", "2.2", true, 128, 0, 1, kZero, kSquareTop, false},
    {"square_tri6_v40_ascii.msh", "4.0", false, 128, 0, 1, kZero, kSquareTop, false},
    {"square_tri6_v41_ascii.msh", "4.1", false, 128, 0, 1, kZero, kSquareTop, false},
    {"square_tri6_v41_bin.msh", "4.1", true, 128, 0, 1, kZero, kSquareTop, false},
    {"square_quad9_v22_ascii.msh", "2.2", false, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad9_v22_bin.msh", "2.2", true, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad9_v40_ascii.msh", "4.0", false, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad9_v41_ascii.msh", "4.1", false, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad9_v41_bin.msh", "4.1", true, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad8_v22_ascii.msh", "2.2", false, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad8_v22_bin.msh", "2.2", true, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad8_v40_ascii.msh", "4.0", false, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad8_v41_ascii.msh", "4.1", false, 0, 64, 1, kZero, kSquareTop, false},
    {"square_quad8_v41_bin.msh", "4.1", true, 0, 64, 1, kZero, kSquareTop, false},
    {"sparse_tags_v22_ascii.msh", "2.2", false, 18, 0, 1, {1, 0, 0}, {2, 1, 0}, false},
    {"sparse_tags_v22_bin.msh", "2.2", true, 18, 0, 1, {1, 0, 0}, {2, 1, 0}, false},
    {"sparse_tags_v41_ascii.msh", "4.1", false, 18, 0, 1, {1, 0, 0}, {2, 1, 0}, false},
    {"sparse_tags_v41_bin.msh", "4.1", true, 18, 0, 1, {1, 0, 0}, {2, 1, 0}, false},
    {"far_square_v22_ascii.msh", "2.2", false, 64, 0, 2, {1e6, -2e6, 5}, {1e6 + 1, -2e6 + 2, 5}, false},
    {"far_square_v41_bin.msh", "4.1", true, 64, 0, 2, {1e6, -2e6, 5}, {1e6 + 1, -2e6 + 2, 5}, false},
    {"cube_hex8_v41_ascii.msh", "4.1", false, 0, 54, 6, kZero, kCubeTop, true},
    {"cube_hex8_v22_bin.msh", "2.2", true, 0, 54, 6, kZero, kCubeTop, true},
    {"cube_hex20_v41_ascii.msh", "4.1", false, 0, 216, 6, kZero, kCubeTop, true},
    {"cube_hex20_v22_bin.msh", "2.2", true, 0, 216, 6, kZero, kCubeTop, true},
    {"cube_hex27_v41_ascii.msh", "4.1", false, 0, 216, 6, kZero, kCubeTop, true},
    {"cube_hex27_v22_bin.msh", "2.2", true, 0, 216, 6, kZero, kCubeTop, true},
    {"prism6_v41_ascii.msh", "4.1", false, 64, 32, 6, kZero, kCubeTop, true},
    {"prism6_v41_bin.msh", "4.1", true, 64, 32, 6, kZero, kCubeTop, true},
    {"prism18_v41_bin.msh", "4.1", true, 64, 32, 6, kZero, kCubeTop, true},
    {"prism15_v22_ascii.msh", "2.2", false, 64, 32, 6, kZero, kCubeTop, true},
};

INSTANTIATE_TEST_SUITE_P(Fixtures, MshFixtureTest, testing::ValuesIn(kFixtures),
                         [](const testing::TestParamInfo<FixtureCase>& param) {
                           return test::fixtureTestName(param.param.file);
                         });

TEST(MshReader, TetrahedraBecomeTheirSkinInEveryFormat) {
  const char* files[] = {"cube_tet4_v22_ascii.msh", "cube_tet4_v22_bin.msh", "cube_tet4_v41_ascii.msh",
                         "cube_tet4_v41_bin.msh"};
  std::uint64_t skinFaces = 0;
  for (const char* file : files) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_GT(mesh.source.volumeElements, 0u);
    EXPECT_EQ(mesh.source.elementsByType.at(4), mesh.source.volumeElements);
    if (skinFaces == 0) skinFaces = mesh.faceCount();
    EXPECT_EQ(mesh.faceCount(), skinFaces);  // the same gmsh mesh in four files
    EXPECT_EQ(stats.quads, 0u);
    EXPECT_NEAR(stats.area, 6.0, 1e-5);
    ASSERT_EQ(stats.shells.size(), 1u);
    EXPECT_TRUE(stats.shells[0].closed);
    EXPECT_TRUE(stats.shells[0].consistentlyOriented);
    EXPECT_NEAR(stats.shells[0].signedVolume, 1.0, 1e-5);
    for (std::uint8_t mask : mesh.faceEdgeMask) EXPECT_EQ(mask, 0b111);
    EXPECT_EQ(mesh.physicalName(mesh.facePhysicalTag[0]), "solid");
  }
  // Ten-node tetrahedra: every skin triangle is split through its edge nodes.
  for (const char* file : {"cube_tet10_v22_ascii.msh", "cube_tet10_v22_bin.msh", "cube_tet10_v41_ascii.msh",
                           "cube_tet10_v41_bin.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_EQ(mesh.faceCount(), 4 * skinFaces);
    EXPECT_NEAR(stats.area, 6.0, 1e-5);
    ASSERT_EQ(stats.shells.size(), 1u);
    EXPECT_TRUE(stats.shells[0].closed);
    EXPECT_TRUE(stats.shells[0].consistentlyOriented);
    EXPECT_NEAR(stats.shells[0].signedVolume, 1.0, 1e-5);
  }
}

// -save_all writes every surface element too, in no physical group: the skin is one face per
// boundary face (no second copy), and it carries the grouped volume's tag, so the volume's material.
TEST(MshReader, UngroupedSurfaceElementsGiveWayToTheGroupedVolumeSkin) {
  const Mesh linear = readMsh(mshFixture("cube_tet4_saveall_v41_ascii.msh"));
  EXPECT_EQ(linear.faceCount(), linear.source.elementsByType.at(2));
  EXPECT_EQ(linear.source.skinFaces, linear.faceCount());
  EXPECT_EQ(linear.source.skinFacesCoveredBySurfaces, 0u);
  for (std::size_t f = 0; f < linear.faceCount(); ++f) ASSERT_EQ(linear.facePhysicalTag[f], 1) << f;
  const Mesh quadratic = readMsh(mshFixture("cube_tet10_saveall_v41_bin.msh"));
  EXPECT_EQ(quadratic.faceCount(), 4 * quadratic.source.elementsByType.at(9));
  EXPECT_EQ(quadratic.source.skinFaces * 4, quadratic.faceCount());
  EXPECT_TRUE(quadratic.volumeSides.empty());  // one volume: no interfaces, nothing more per face
  const MeshStats stats = computeMeshStats(quadratic);
  EXPECT_NEAR(stats.area, 6.0, 1e-5);
  EXPECT_TRUE(stats.shells.size() == 1 && stats.shells[0].closed && stats.shells[0].consistentlyOriented);
}

TEST(MshReader, PhysicalGroupsAndTheirNames) {
  for (const char* file :
       {"square_tri3_v22_ascii.msh", "square_tri3_v41_bin.msh", "square_tri3_v40_ascii.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    ASSERT_EQ(mesh.physicalGroups.size(), 3u);
    EXPECT_EQ(mesh.physicalGroups[0].dimension, 1);
    EXPECT_EQ(mesh.physicalGroups[0].name, "rim");
    EXPECT_EQ(mesh.physicalGroups[1].dimension, 2);
    EXPECT_EQ(mesh.physicalGroups[1].name, "plate");
    EXPECT_EQ(mesh.physicalGroups[2].name, "everything");
    // An element in two groups belongs to the first; MSH 2 writes it twice, lancer keeps one copy.
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      EXPECT_EQ(mesh.physicalName(mesh.facePhysicalTag[f]), "plate");
      EXPECT_EQ(mesh.faceEntityTag[f], 1);
    }
    EXPECT_EQ(mesh.source.elementsByType.at(1), 16u);  // boundary lines: read, counted, not rendered
    EXPECT_EQ(mesh.source.elementsByType.at(2), 32u);
    EXPECT_TRUE(mesh.source.unrenderableByType.empty());
  }
}

TEST(MshReader, EdgeMasksMarkTheOriginalElementEdges) {
  auto maskCounts = [](const char* file) {
    const Mesh mesh = readMsh(mshFixture(file));
    std::map<int, int> counts;
    for (std::uint8_t mask : mesh.faceEdgeMask) ++counts[mask];
    return counts;
  };
  EXPECT_EQ(maskCounts("square_tri3_v41_ascii.msh"), (std::map<int, int>{{0b111, 32}}));
  EXPECT_EQ(maskCounts("square_quad4_v41_ascii.msh"), (std::map<int, int>{{0b1111, 16}}));
  EXPECT_EQ(maskCounts("square_tri6_v41_ascii.msh"),
            (std::map<int, int>{{0, 32}, {0b011, 32}, {0b101, 32}, {0b110, 32}}));
  const std::map<int, int> quadChildren{{0b0011, 16}, {0b0110, 16}, {0b1001, 16}, {0b1100, 16}};
  EXPECT_EQ(maskCounts("square_quad9_v41_bin.msh"), quadChildren);
  EXPECT_EQ(maskCounts("square_quad8_v22_ascii.msh"), quadChildren);
}

TEST(MshReader, SplitSecondOrderFacesKeepTheParentWinding) {
  // Every child of the flat square faces +z like the gmsh elements it came from.
  for (const char* file :
       {"square_tri6_v41_ascii.msh", "square_quad9_v41_bin.msh", "square_quad8_v22_ascii.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    for (const MeshFace& face : mesh.faces) {
      const Vec3 a = mesh.positions[face.vertex[0]], b = mesh.positions[face.vertex[1]],
                 c = mesh.positions[face.vertex[2]];
      EXPECT_GT(cross(b - a, c - a).z, 0.0f);
    }
  }
}

TEST(MshReader, EightNodeQuadCentreIsTheSerendipityCentre) {
  // For straight-sided cells the serendipity centre (-1/4 corners + 1/2 edge nodes) is the cell centre.
  const Mesh mesh = readMsh(mshFixture("square_quad8_v41_ascii.msh"));
  EXPECT_EQ(mesh.source.nodeCount, 65u);
  EXPECT_EQ(mesh.positions.size(), 81u);
  std::set<std::pair<long, long>> points;
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3d p = mesh.worldPosition(v);
    points.insert({std::lround(p.x * 8), std::lround(p.y * 8)});
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_TRUE(points.count({2 * i + 1, 2 * j + 1})) << i << "," << j;
}

TEST(MshReader, ThirdOrderTrianglesAreSplitThroughAllTheirNodes) {
  for (const char* file :
       {"square_tri10_v22_ascii.msh", "square_tri10_v22_bin.msh", "square_tri10_v40_ascii.msh",
        "square_tri10_v41_ascii.msh", "square_tri10_v41_bin.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    // 32 10-node triangles, 9 flat faces each, over all 169 nodes of the unit square.
    EXPECT_EQ(mesh.faceCount(), 32u * 9u);
    EXPECT_EQ(mesh.positions.size(), 169u);
    EXPECT_TRUE(mesh.source.unrenderableByType.empty());
    EXPECT_EQ(mesh.source.elementsByType.at(26), 16u);  // 4-node lines are skipped
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_NEAR(stats.area, 1.0, 1e-12);
    // The split faces share their vertices and keep the element's winding: one open shell.
    ASSERT_EQ(stats.shells.size(), 1u);
    EXPECT_TRUE(stats.shells[0].consistentlyOriented);
    // Element edges: the outer edges of the 9 faces, 3 per element edge.
    std::size_t drawnEdges = 0;
    for (const std::uint8_t mask : mesh.faceEdgeMask)
      drawnEdges += static_cast<std::size_t>(std::popcount(mask));
    EXPECT_EQ(drawnEdges, 32u * 9u);
  }
}

TEST(MshReader, SphereIsAClosedOutwardShellNearFourPi) {
  const Mesh whole = readMsh(mshFixture("sphere_v41_ascii.msh"));
  const double fourPi = 4 * std::numbers::pi;
  for (const char* file :
       {"sphere_v41_ascii.msh", "sphere_v41_bin.msh", "sphere_v22_ascii.msh", "sphere_part2_v41_ascii.msh",
        "sphere_part2_v41_bin.msh", "sphere_part2_v22_ascii.msh", "sphere_part2_v22_bin.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_EQ(mesh.faceCount(), whole.faceCount());
    // Inscribed triangles: a little less area than the sphere, at most 3% for this mesh size.
    EXPECT_LT(stats.area, fourPi);
    EXPECT_GT(stats.area, 0.97 * fourPi);
    ASSERT_EQ(stats.shells.size(), 1u);
    EXPECT_TRUE(stats.shells[0].closed);
    EXPECT_TRUE(stats.shells[0].consistentlyOriented);
    EXPECT_GT(stats.shells[0].signedVolume, 0.95 * 4 / 3 * std::numbers::pi);
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      ASSERT_EQ(mesh.physicalName(mesh.facePhysicalTag[f]), "ball");
      ASSERT_EQ(mesh.faceEntityTag[f], 1);  // partitioned entities map back to the model surface
    }
    const bool partitioned = std::string(file).find("part2") != std::string::npos;
    EXPECT_EQ(mesh.source.partitionCount, partitioned ? 2u : 0u);
  }
}

TEST(MshReader, FarCoordinatesAreRecentredWithoutLosingPrecision) {
  for (const char* file : {"far_square_v41_bin.msh", "far_square_v22_ascii.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(mshFixture(file));
    EXPECT_NEAR(mesh.origin.x, 1e6 + 0.5, 1e-9);
    EXPECT_NEAR(mesh.origin.y, -2e6 + 1, 1e-9);
    EXPECT_NEAR(mesh.origin.z, 5, 1e-9);
    // Nodes sit on a 0.25 x 0.25 grid; float offsets from the centre keep that exactly.
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
      const Vec3d p = mesh.worldPosition(v);
      EXPECT_NEAR((p.x - 1e6) * 4, std::round((p.x - 1e6) * 4), 1e-6);
      EXPECT_NEAR((p.y + 2e6) * 4, std::round((p.y + 2e6) * 4), 1e-6);
      EXPECT_LE(std::abs(mesh.positions[v].y), 1.0f);
    }
  }
}

TEST(MshReader, MemoryAndFileReadsAgree) {
  const std::string path = mshFixture("square_quad9_v41_bin.msh");
  const std::vector<char> bytes = test::readFileBytes(path);
  const Mesh fromFile = readMsh(path);
  const Mesh fromMemory = readMshFromMemory(bytes, "in-memory.msh");
  ASSERT_EQ(fromFile.faceCount(), fromMemory.faceCount());
  for (std::size_t f = 0; f < fromFile.faceCount(); ++f)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(fromFile.faces[f].vertex[c], fromMemory.faces[f].vertex[c]);
  EXPECT_EQ(fromMemory.source.path, "in-memory.msh");
  EXPECT_EQ(fromFile.source.fileBytes, bytes.size());
}

// Pyramids and degenerate faces: gmsh does not make these from a simple .geo, so the files are
// spelled out here in MSH 2.2 ASCII.
Mesh readText(const std::string& text) {
  return readMshFromMemory(std::span<const char>(text.data(), text.size()), "text.msh");
}

TEST(MshReader, PyramidSkinIsClosedAndOutward) {
  const Mesh mesh = readText(
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n"
      "1 -1 -1 0\n2 1 -1 0\n3 1 1 0\n4 -1 1 0\n5 0 0 1\n$EndNodes\n"
      "$Elements\n1\n1 7 2 0 1 1 2 3 4 5\n$EndElements\n");
  const MeshStats stats = computeMeshStats(mesh);
  EXPECT_EQ(stats.quads, 1u);
  EXPECT_EQ(stats.triangles, 4u);
  ASSERT_EQ(stats.shells.size(), 1u);
  EXPECT_TRUE(stats.shells[0].closed);
  EXPECT_TRUE(stats.shells[0].consistentlyOriented);
  EXPECT_NEAR(stats.shells[0].signedVolume, 4.0 / 3.0, 1e-6);
}

TEST(MshReader, DegenerateFacesAreDroppedAndCounted) {
  const Mesh mesh = readText(
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
      "1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n$EndNodes\n"
      "$Elements\n3\n1 2 2 0 1 1 2 4\n2 2 2 0 1 1 2 3\n3 2 2 0 1 1 1 4\n$EndElements\n");
  EXPECT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.source.degenerateFacesDropped, 2u);
  EXPECT_EQ(mesh.positions.size(), 4u);  // nodes of dropped faces stay (unused ones would not)
}

TEST(MshReader, UnusedNodesAreNotKept) {
  const Mesh mesh = readMsh(mshFixture("square_tri3_v41_ascii.msh"));
  EXPECT_EQ(mesh.source.nodeCount, 25u);
  EXPECT_EQ(mesh.positions.size(), 25u);
  const Mesh skin = readMsh(mshFixture("cube_hex8_v41_ascii.msh"));
  EXPECT_EQ(skin.source.nodeCount, 64u);
  EXPECT_EQ(skin.positions.size(), 56u);  // the 8 interior nodes of the 4 x 4 x 4 grid are dropped
}

TEST(MshNodeTable, SparseAndHugeTagsUseTheSortedLookup) {
  MshNodeTable table;
  table.add(5, {0, 0, 0});
  table.add(1'000'000'000'000ull, {1, 0, 0});
  table.add(3, {2, 0, 0});
  EXPECT_FALSE(table.buildLookup().has_value());
  EXPECT_EQ(table.find(5), 0u);
  EXPECT_EQ(table.find(1'000'000'000'000ull), 1u);
  EXPECT_EQ(table.find(3), 2u);
  EXPECT_EQ(table.find(4), kNoVertex);
  EXPECT_EQ(table.find(0), kNoVertex);
  table.add(3, {3, 0, 0});
  EXPECT_EQ(table.buildLookup(), std::optional<std::uint64_t>(3));
}

TEST(MshNodeTable, DenseLookupRefusesTagsOutsideTheRange) {
  MshNodeTable table;
  for (std::uint64_t tag = 10; tag < 20; ++tag) table.add(tag, {});
  EXPECT_FALSE(table.buildLookup().has_value());
  EXPECT_EQ(table.find(10), 0u);
  EXPECT_EQ(table.find(19), 9u);
  EXPECT_EQ(table.find(9), kNoVertex);
  EXPECT_EQ(table.find(20000), kNoVertex);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

TEST(MshElementTypes, NodeCountsAndRolesFollowGmsh) {
  EXPECT_EQ(mshElementType(2).nodeCount, 3);
  EXPECT_EQ(mshElementType(16).nodeCount, 8);
  EXPECT_EQ(mshElementType(29).nodeCount, 20);
  EXPECT_EQ(mshElementType(92).nodeCount, 64);
  EXPECT_EQ(mshElementType(117).nodeCount, 78);
  EXPECT_EQ(mshElementType(131).nodeCount, 69);
  EXPECT_EQ(mshElementType(140).nodeCount, 4);
  EXPECT_EQ(mshElementType(76).nodeCount, 0);  // unused number
  EXPECT_EQ(mshElementType(0).nodeCount, 0);
  EXPECT_EQ(mshElementType(141).nodeCount, 0);
  EXPECT_EQ(mshElementType(15).role, MshElementRole::kIgnored);
  EXPECT_EQ(mshElementType(26).role, MshElementRole::kIgnored);
  EXPECT_EQ(mshElementType(9).role, MshElementRole::kSurface);
  EXPECT_EQ(mshElementType(19).role, MshElementRole::kVolume);
  EXPECT_EQ(mshElementType(21).role, MshElementRole::kSurface);        // 10-node triangle
  EXPECT_EQ(mshElementType(36).role, MshElementRole::kSurface);        // 16-node quadrangle
  EXPECT_EQ(mshElementType(29).role, MshElementRole::kVolume);         // 20-node tetrahedron
  EXPECT_EQ(mshElementType(92).role, MshElementRole::kVolume);         // 64-node hexahedron
  EXPECT_EQ(mshElementType(34).role, MshElementRole::kUnrenderable);   // polygon
  EXPECT_EQ(mshElementType(84).role, MshElementRole::kUnrenderable);   // 1-node line
  EXPECT_EQ(mshElementType(140).role, MshElementRole::kUnrenderable);  // trihedron
  EXPECT_EQ(mshCompleteSurfaceOrder(21), 3);
  EXPECT_EQ(mshCompleteSurfaceOrder(40), 0);  // 16-node quadrangle of order 4, incomplete
  EXPECT_EQ(mshCompleteSurfaceOrder(51), 10);
  EXPECT_EQ(mshElementType(29).dimension, 3);
  EXPECT_EQ(mshElementTypeName(11), "10-node tetrahedron");
  EXPECT_EQ(mshElementTypeName(34), "variable-size polygon");
  EXPECT_EQ(mshElementTypeName(500), "type 500");
}

}  // namespace
}  // namespace lancer
