// Face shells: which faces share edges, which shells are closed, and how each face of a closed shell
// must be turned for the shell to agree (the parity union-find of parity_disjoint_sets.hpp), on
// orientable and non-orientable surfaces and for any thread count.
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/face_shells.hpp"
#include "lancer/mesh/shell_orientation.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

// Every shared edge of the faces is traversed once each way.
bool agrees(const std::vector<MeshFace>& faces) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const MeshFace& face : faces)
    for (int c = 0; c < face.cornerCount(); ++c)
      if (++directed[{face.vertex[c], face.vertex[(c + 1) % face.cornerCount()]}] > 1) return false;
  return true;
}

TEST(FaceShells, FlipBitsTurnAScrambledSphereIntoAnAgreeingOne) {
  test::Soup sphere = test::sphere(40, 50);
  std::vector<MeshFace> faces = sphere.faces;
  std::uint8_t unusedMask = kAllEdges;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if ((f * 7919) % 5 < 2) reverseWinding(faces[f], unusedMask);
  ASSERT_FALSE(agrees(faces));
  for (const int threads : {1, 2, 5}) {
    const FaceShells shells = findFaceShells(faces, threads);
    ASSERT_EQ(shells.shellCount(), 1u);
    EXPECT_TRUE(shells.closed[0]);
    EXPECT_FALSE(shells.consistent[0]);
    EXPECT_TRUE(shells.orientable[0]);
    EXPECT_EQ(shells.flip[0], 0);  // relative to the shell's first face
    std::vector<MeshFace> turned = faces;
    for (std::size_t f = 0; f < turned.size(); ++f)
      if (shells.flip[f]) reverseWinding(turned[f], unusedMask);
    EXPECT_TRUE(agrees(turned)) << threads << " threads";
  }
}

// The real projective plane with 6 vertices and 10 triangles: closed (every edge shared by two
// faces) but no choice of windings agrees along every edge.
std::vector<MeshFace> projectivePlane() {
  const std::uint32_t triangles[10][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
                                          {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
  std::vector<MeshFace> faces;
  for (const auto& t : triangles) faces.push_back(MeshFace{{t[0], t[1], t[2], kNoVertex}});
  return faces;
}

TEST(FaceShells, AProjectivePlaneIsClosedButNotOrientable) {
  const std::vector<MeshFace> faces = projectivePlane();
  const FaceShells shells = findFaceShells(faces, 1);
  ASSERT_EQ(shells.shellCount(), 1u);
  EXPECT_TRUE(shells.closed[0]);
  EXPECT_FALSE(shells.orientable[0]);

  // Orientation leaves it as the file has it and reports it.
  const std::vector<Vec3> positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  std::vector<MeshFace> oriented = faces;
  std::vector<std::uint8_t> masks;
  const ShellOrientationReport report = orientClosedShellsOutward(positions, oriented, masks, {}, {}, 1);
  EXPECT_EQ(report.closedShells, 1u);
  EXPECT_EQ(report.unorientableShells, 1u);
  EXPECT_EQ(report.flippedFaces, 0u);
  EXPECT_EQ(std::memcmp(oriented.data(), faces.data(), faces.size() * sizeof(MeshFace)), 0);
}

TEST(FaceShells, ShellsAreNumberedInOrderOfTheirFirstFace) {
  // Two spheres, the second's faces first, then an open strip with a degenerate face.
  test::Soup a = test::sphere(8, 10), b = test::sphere(6, 7, {3, 0, 0});
  std::vector<MeshFace> faces;
  const auto offset = static_cast<std::uint32_t>(a.positions.size());
  for (MeshFace face : b.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += offset;
    faces.push_back(face);
  }
  faces.insert(faces.end(), a.faces.begin(), a.faces.end());
  const std::uint32_t strip = offset + static_cast<std::uint32_t>(b.positions.size());
  faces.push_back(MeshFace{{strip, strip + 1, strip + 2, kNoVertex}});
  faces.push_back(MeshFace{{strip + 2, strip + 1, strip + 3, kNoVertex}});
  faces.push_back(MeshFace{{strip + 3, strip + 3, strip + 1, kNoVertex}});  // an edge from v to v
  for (const int threads : {1, 3}) {
    const FaceShells shells = findFaceShells(faces, threads);
    ASSERT_EQ(shells.shellCount(), 3u);
    EXPECT_EQ(shells.shellOfFace.front(), 0u);
    EXPECT_EQ(shells.shellOfFace[b.faces.size()], 1u);
    EXPECT_EQ(shells.shellOfFace.back(), 2u);
    EXPECT_TRUE(shells.closed[0] && shells.closed[1]);
    EXPECT_TRUE(shells.consistent[0] && shells.consistent[1]);
    EXPECT_FALSE(shells.closed[2]);
  }
}

}  // namespace
}  // namespace lancer
