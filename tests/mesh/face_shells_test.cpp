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

TEST(FaceShells, InterleavedAgreeingShellsAreComponentsOnAnyThreadCount) {
  // Agreeing closed shells (every edge of two faces, traversed both ways) are found on every thread
  // at once: their faces interleaved, in chunks of vertices that start mid-shell, numbered as the
  // components of the face graph in order of their first face, no face to flip.
  std::vector<test::Soup> spheres;
  for (int s = 0; s < 6; ++s) spheres.push_back(test::sphere(90 + s, 100, {3.0f * s, 0, 0}));
  std::vector<MeshFace> faces;
  std::vector<std::uint32_t> offset(spheres.size(), 0);
  for (std::size_t s = 1; s < spheres.size(); ++s)
    offset[s] = offset[s - 1] + static_cast<std::uint32_t>(spheres[s - 1].positions.size());
  for (std::size_t f = 0;; ++f) {
    bool any = false;
    for (std::size_t k = spheres.size(); k-- > 0;) {  // the last sphere's faces first
      if (f >= spheres[k].faces.size()) continue;
      any = true;
      if (k % 2 == 1 && f % 3 == 0) continue;
      MeshFace face = spheres[k].faces[f];
      for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += offset[k];
      faces.push_back(face);
    }
    if (!any) break;
  }
  for (std::size_t k = 1; k < spheres.size(); k += 2)  // the faces skipped above, at the end
    for (std::size_t f = 0; f < spheres[k].faces.size(); f += 3) {
      MeshFace face = spheres[k].faces[f];
      for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += offset[k];
      faces.push_back(face);
    }
  ASSERT_TRUE(agrees(faces));
  ASSERT_GT(faces.size(), 2u * 16384);  // several chunks of vertices
  // Expected: the sphere of each face, numbered by first appearance.
  std::vector<std::uint32_t> sphereOf(faces.size()), number(spheres.size(), 0xFFFFFFFFu);
  std::uint32_t next = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::size_t k = spheres.size() - 1;
    while (faces[f].vertex[0] < offset[k]) --k;
    if (number[k] == 0xFFFFFFFFu) number[k] = next++;
    sphereOf[f] = number[k];
  }
  for (const int threads : {1, 2, 5}) {
    const FaceShells shells = findFaceShells(faces, threads);
    ASSERT_EQ(shells.shellCount(), spheres.size());
    EXPECT_EQ(shells.shellOfFace, sphereOf);
    for (std::size_t s = 0; s < spheres.size(); ++s) {
      EXPECT_TRUE(shells.closed[s] && shells.consistent[s] && shells.orientable[s]);
      EXPECT_FALSE(shells.bordered[s] || shells.branched[s]);
    }
    EXPECT_EQ(std::count(shells.flip.begin(), shells.flip.end(), 0), static_cast<long>(faces.size()));
    EXPECT_TRUE(shells.edges.empty());  // found without the sorted table
  }
  // One face turned: the shells are walked with their parities, the turned face to flip.
  std::uint8_t unusedMask = kAllEdges;
  reverseWinding(faces[1000], unusedMask);
  for (const int threads : {1, 2}) {
    const FaceShells shells = findFaceShells(faces, threads);
    EXPECT_EQ(shells.shellOfFace, sphereOf);
    EXPECT_FALSE(shells.consistent[sphereOf[1000]]);
    EXPECT_TRUE(shells.orientable[sphereOf[1000]]);
    std::size_t corners = 0;
    for (const MeshFace& face : faces) corners += static_cast<std::size_t>(face.cornerCount());
    EXPECT_EQ(shells.edges.size(), corners);  // walked over the sorted table
    for (std::size_t f = 0; f < faces.size(); ++f) ASSERT_EQ(shells.flip[f], f == 1000 ? 1 : 0) << f;
  }
}

}  // namespace
}  // namespace lancer
