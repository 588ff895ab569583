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
