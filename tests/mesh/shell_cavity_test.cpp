// Cavity walls face into the cavity: gmsh's hollow sphere (tetrahedra between radii 1 and 0.5, one
// physical volume) keeps its outer shell at positive volume and its inner shell at negative volume,
// whatever the file's winding; two concentric spheres of different physical groups are separate
// solids and both face outward (tests/data/render/hollow_sphere.geo, nested_spheres.geo).
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/shell_nesting.hpp"
#include "lancer/mesh/shell_orientation.hpp"

namespace lancer {
namespace {

constexpr const char* kDataDir = LANCER_TEST_DATA_DIR "/render/";

constexpr double kOuterVolume = 4.0 / 3.0 * std::numbers::pi;      // radius 1
constexpr double kInnerVolume = 4.0 / 3.0 * std::numbers::pi / 8;  // radius 0.5

ShellOrientationReport orient(Mesh& mesh) {
  return orientClosedShellsOutward(mesh.positions, mesh.faces, mesh.faceEdgeMask, mesh.facePhysicalTag);
}

// The two shells' signed volumes, outer (more faces) first; gmsh's facets lie inside the spheres.
void expectVolumes(const Mesh& mesh, double outerSign, double innerSign) {
  const MeshStats stats = computeMeshStats(mesh);
  ASSERT_EQ(stats.shells.size(), 2u);
  for (const MeshShell& shell : stats.shells) {
    EXPECT_TRUE(shell.closed);
    EXPECT_TRUE(shell.consistentlyOriented);
  }
  EXPECT_GT(outerSign * stats.shells[0].signedVolume, 0.9 * kOuterVolume);
  EXPECT_LT(outerSign * stats.shells[0].signedVolume, kOuterVolume);
  EXPECT_GT(innerSign * stats.shells[1].signedVolume, 0.8 * kInnerVolume);
  EXPECT_LT(innerSign * stats.shells[1].signedVolume, kInnerVolume);
}

void reverseAll(Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) reverseWinding(mesh.faces[f], mesh.faceEdgeMask[f]);
}

TEST(ShellCavity, HollowSphereInnerShellFacesIntoTheCavity) {
  Mesh mesh = readMsh(std::string(kDataDir) + "hollow_sphere.msh");
  ASSERT_EQ(mesh.physicalGroups.size(), 1u);
  expectVolumes(mesh, 1, -1);  // the tetrahedra's skin, wound out of the material
  const ShellOrientationReport report = orient(mesh);
  EXPECT_EQ(report.closedShells, 2u);
  EXPECT_EQ(report.cavityShells, 1u);
  EXPECT_EQ(report.flippedFaces, 0u);
  expectVolumes(mesh, 1, -1);
  for (std::uint8_t solid : report.faceBoundsSolid) EXPECT_EQ(solid, 1);
}

TEST(ShellCavity, HollowSphereWoundInsideOutComesBackWithTheCavityFacingIn) {
  Mesh mesh = readMsh(std::string(kDataDir) + "hollow_sphere.msh");
  reverseAll(mesh);
  expectVolumes(mesh, -1, 1);
  const ShellOrientationReport report = orient(mesh);
  EXPECT_EQ(report.cavityShells, 1u);
  EXPECT_EQ(report.flippedFaces, mesh.faces.size());
  expectVolumes(mesh, 1, -1);
}

TEST(ShellCavity, HollowSphereWithSomeFacesFlippedComesBackConsistent) {
  Mesh mesh = readMsh(std::string(kDataDir) + "hollow_sphere.msh");
  for (std::size_t f = 0; f < mesh.faces.size(); f += 3) reverseWinding(mesh.faces[f], mesh.faceEdgeMask[f]);
  orient(mesh);
  expectVolumes(mesh, 1, -1);
}

TEST(ShellCavity, ConcentricSpheresOfDifferentGroupsBothFaceOutward) {
  Mesh mesh = readMsh(std::string(kDataDir) + "nested_spheres.msh");
  ASSERT_EQ(mesh.physicalGroups.size(), 2u);
  reverseAll(mesh);
  const ShellOrientationReport report = orient(mesh);
  EXPECT_EQ(report.closedShells, 2u);
  EXPECT_EQ(report.cavityShells, 0u);
  expectVolumes(mesh, 1, 1);
}

TEST(ShellCavity, ConcentricSpheresOfOneGroupAreAHollowSolid) {
  // The same surfaces put in one group (or in none: tag 0 for every face) bound one hollow solid.
  for (const bool untagged : {false, true}) {
    Mesh mesh = readMsh(std::string(kDataDir) + "nested_spheres.msh");
    for (std::int32_t& tag : mesh.facePhysicalTag) tag = untagged ? 0 : 7;
    const ShellOrientationReport report = orient(mesh);
    EXPECT_EQ(report.cavityShells, 1u) << untagged;
    expectVolumes(mesh, 1, -1);
  }
}

TEST(ShellCavity, EmptyTagListMeansOneGroup) {
  Mesh mesh = readMsh(std::string(kDataDir) + "nested_spheres.msh");
  const ShellOrientationReport report = orientClosedShellsOutward(
      mesh.positions, mesh.faces, mesh.faceEdgeMask, std::span<const std::int32_t>{});
  EXPECT_EQ(report.cavityShells, 1u);
  expectVolumes(mesh, 1, -1);
}

TEST(ShellCavity, ShellsSideBySideAreNoCavities) {
  // The small sphere moved out of the big one: neither box contains the other.
  Mesh mesh = readMsh(std::string(kDataDir) + "nested_spheres.msh");
  const FaceShells shells = findFaceShells(mesh.faces);
  ASSERT_EQ(shells.shellCount(), 2u);
  for (Vec3& p : mesh.positions)
    if (length(p) < 0.75f) p.x += 3.0f;
  const std::vector<std::uint8_t> all(2, 1);
  const std::vector<std::uint8_t> cavity =
      findCavityShells(mesh.positions, mesh.faces, shells, std::span<const std::int32_t>{}, all);
  EXPECT_EQ(cavity, std::vector<std::uint8_t>(2, 0));
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// An animation keeps the orientation of its first frame while the shells keep facing out of their
// solids: the hollow sphere's shells (one a cavity wall) still do when it is squashed and moved,
// not when the mesh is mirrored (each shell's volume changes sign) or when the cavity alone is
// turned inside out; a non-manifold surface (regions, not shells) is not kept.
TEST(ShellCavity, KeptOrientationHoldsUnderADeformationThatTurnsNoShellInsideOut) {
  Mesh mesh = readMsh(std::string(kDataDir) + "hollow_sphere.msh");
  OrientedShells oriented;
  orientClosedShellsOutward(mesh.positions, mesh.faces, mesh.faceEdgeMask, mesh.facePhysicalTag, {}, 2,
                            &oriented);
  ASSERT_TRUE(oriented.kept);
  EXPECT_EQ(std::count(oriented.cavity.begin(), oriented.cavity.end(), 1), 1);
  for (const int threads : {1, 2}) {
    EXPECT_TRUE(shellsKeepOrientation(mesh.positions, mesh.faces, oriented, threads));
    std::vector<Vec3> squashed = mesh.positions;
    for (Vec3& p : squashed) p = Vec3{2.0f * p.x + 5.0f, 0.3f * p.y, p.z + 0.1f * p.x * p.x};
    EXPECT_TRUE(shellsKeepOrientation(squashed, mesh.faces, oriented, threads));
    std::vector<Vec3> mirrored = mesh.positions;
    for (Vec3& p : mirrored) p.x = -p.x;
    EXPECT_FALSE(shellsKeepOrientation(mirrored, mesh.faces, oriented, threads));
    // The inner shell (radius 0.5) pushed out through the outer radius, inside out.
    std::vector<Vec3> everted = mesh.positions;
    for (Vec3& p : everted)
      if (length(p) < 0.75f) p = p * (-1.0f);
    EXPECT_FALSE(shellsKeepOrientation(everted, mesh.faces, oriented, threads));
  }
  // Three squares meeting on one edge: regions of a non-manifold surface, oriented by where they lie.
  std::vector<Vec3> positions = {{0, 0, 0},  {0, 0, 1},  {1, 0, 0}, {1, 0, 1},
                                 {-1, 0, 0}, {-1, 0, 1}, {0, 1, 0}, {0, 1, 1}};
  std::vector<MeshFace> faces = {{{0, 2, 3, 1}}, {{0, 1, 5, 4}}, {{0, 6, 7, 1}}};
  std::vector<std::uint8_t> masks;
  OrientedShells fan;
  orientClosedShellsOutward(positions, faces, masks, std::vector<std::int32_t>(3, 1), {}, 1, &fan);
  EXPECT_FALSE(fan.kept);
  EXPECT_FALSE(shellsKeepOrientation(positions, faces, fan));
}

}  // namespace
}  // namespace lancer
