// Closed shells are oriented outward whatever the file's winding: gmsh's sphere and hexahedral cube
// with faces flipped (some, or all) come back consistent with a positive volume; open surfaces keep
// the file's winding.
#include "lancer/mesh/shell_orientation.hpp"

#include <gtest/gtest.h>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

Vec3d faceCentroid(const Mesh& mesh, const MeshFace& face) {
  Vec3d sum{0, 0, 0};
  for (int c = 0; c < face.cornerCount(); ++c) sum += toDouble(mesh.positions[face.vertex[c]]);
  return sum * (1.0 / face.cornerCount());
}

Vec3d faceNormalOf(const Mesh& mesh, const MeshFace& face) {
  const Vec3d a = toDouble(mesh.positions[face.vertex[0]]);
  const Vec3d b = toDouble(mesh.positions[face.vertex[1]]);
  const Vec3d c = toDouble(mesh.positions[face.vertex[2]]);
  return cross(b - a, c - a);
}

// Counts faces whose normal points away from the centre of the mesh's box, for convex shells.
int outwardFaces(const Mesh& mesh) {
  const Vec3d centre = toDouble(faceBounds(mesh).center());
  int outward = 0;
  for (const MeshFace& face : mesh.faces)
    outward += dot(faceNormalOf(mesh, face), faceCentroid(mesh, face) - centre) > 0;
  return outward;
}

void flipEvery(Mesh& mesh, int period, int phase) {
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (static_cast<int>(f % period) == phase) reverseWinding(mesh.faces[f], mesh.faceEdgeMask[f]);
}

ShellOrientationReport orient(Mesh& mesh) {
  return orientClosedShellsOutward(mesh.positions, mesh.faces, mesh.faceEdgeMask, mesh.facePhysicalTag);
}

TEST(ShellOrientation, GmshSphereWithFlippedFacesComesBackOutward) {
  Mesh mesh = readMsh(test::mshFixture("sphere_v41_ascii.msh"));
  const int faceCount = static_cast<int>(mesh.faces.size());
  ASSERT_EQ(outwardFaces(mesh), faceCount);  // gmsh wrote it outward
  const double volume = computeMeshStats(mesh).shells.at(0).signedVolume;
  ASSERT_GT(volume, 3.5);  // close to 4/3 pi
  flipEvery(mesh, 3, 1);
  ASSERT_FALSE(computeMeshStats(mesh).shells.at(0).consistentlyOriented);

  const ShellOrientationReport report = orient(mesh);
  EXPECT_EQ(report.shells, 1u);
  EXPECT_EQ(report.closedShells, 1u);
  EXPECT_EQ(report.unorientableShells, 0u);
  EXPECT_EQ(report.flippedFaces, static_cast<std::uint64_t>((faceCount + 1) / 3));
  EXPECT_EQ(outwardFaces(mesh), faceCount);
  const MeshShell shell = computeMeshStats(mesh).shells.at(0);
  EXPECT_TRUE(shell.consistentlyOriented);
  EXPECT_NEAR(shell.signedVolume, volume, 1e-9);
  for (std::uint8_t solid : report.faceBoundsSolid) EXPECT_EQ(solid, 1);
}

TEST(ShellOrientation, InwardSphereIsTurnedInsideOut) {
  // Every face flipped, and then one back: the majority winding is inward, the volume decides.
  Mesh mesh = readMsh(test::mshFixture("sphere_v41_bin.msh"));
  flipEvery(mesh, 1, 0);
  reverseWinding(mesh.faces[5], mesh.faceEdgeMask[5]);
  const ShellOrientationReport report = orient(mesh);
  EXPECT_EQ(report.flippedFaces, mesh.faces.size() - 1);
  EXPECT_EQ(outwardFaces(mesh), static_cast<int>(mesh.faces.size()));
  EXPECT_GT(computeMeshStats(mesh).shells.at(0).signedVolume, 3.5);
}

TEST(ShellOrientation, GmshHexCubeSkinOfQuads) {
  Mesh mesh = readMsh(test::mshFixture("cube_hex8_v41_ascii.msh"));  // 54 skin quads
  ASSERT_EQ(mesh.faces.size(), 54u);
  flipEvery(mesh, 4, 2);
  orient(mesh);
  EXPECT_EQ(outwardFaces(mesh), 54);
  const MeshShell shell = computeMeshStats(mesh).shells.at(0);
  EXPECT_TRUE(shell.consistentlyOriented);
  EXPECT_NEAR(shell.signedVolume, 1.0, 1e-6);
}

// One solid: its faces are one run, kept for an animation; a stretch keeps it facing out, a mirror
// turns it inside out.
TEST(ShellOrientation, KeptAsOneRunForASingleSolid) {
  Mesh mesh = readMsh(test::mshFixture("cube_hex8_v41_ascii.msh"));
  flipEvery(mesh, 4, 2);
  OrientedShells oriented;
  orientClosedShellsOutward(mesh.positions, mesh.faces, mesh.faceEdgeMask, mesh.facePhysicalTag, {}, 1,
                            &oriented);
  ASSERT_TRUE(oriented.kept);
  ASSERT_EQ(oriented.runs.size(), 1u);
  EXPECT_TRUE(oriented.faceShell.empty());
  std::vector<Vec3> stretched = mesh.positions;
  for (Vec3& p : stretched) p = Vec3{3 * p.x, p.y + p.x, p.z};
  EXPECT_TRUE(shellsKeepOrientation(stretched, mesh.faces, oriented));
  for (Vec3& p : stretched) p.z = -p.z;
  EXPECT_FALSE(shellsKeepOrientation(stretched, mesh.faces, oriented));
}

TEST(ShellOrientation, OpenSurfaceKeepsTheFilesWinding) {
  Mesh mesh = readMsh(test::mshFixture("square_tri3_v41_ascii.msh"));
  flipEvery(mesh, 2, 0);
  const std::vector<MeshFace> before = mesh.faces;
  const ShellOrientationReport report = orient(mesh);
  EXPECT_EQ(report.closedShells, 0u);
  EXPECT_EQ(report.flippedFaces, 0u);
  for (std::size_t f = 0; f < before.size(); ++f) {
    for (int c = 0; c < 4; ++c) EXPECT_EQ(mesh.faces[f].vertex[c], before[f].vertex[c]);
    EXPECT_EQ(report.faceBoundsSolid[f], 0);
  }
}

TEST(ShellOrientation, ReverseWindingKeepsEdgeMaskOnTheSameEdges) {
  // Quad (0,1,2,3) with only edge 1->2 (bit 1) original: reversed (0,3,2,1) has it as 2->1, bit 2.
  MeshFace quad{{0, 1, 2, 3}};
  std::uint8_t mask = 0b0010;
  reverseWinding(quad, mask);
  EXPECT_EQ(quad.vertex[1], 3u);
  EXPECT_EQ(quad.vertex[3], 1u);
  EXPECT_EQ(mask, 0b0100);
  // Triangle (0,1,2) with edges 0->1 and 2->0 (bits 0, 2): reversed (0,2,1) has 1->0 and 0->2 (bits 2, 0).
  MeshFace triangle{{0, 1, 2, kNoVertex}};
  std::uint8_t triangleMask = 0b0101;
  reverseWinding(triangle, triangleMask);
  EXPECT_EQ(triangle.vertex[1], 2u);
  EXPECT_EQ(triangle.vertex[3], kNoVertex);
  EXPECT_EQ(triangleMask, 0b0101);
  std::uint8_t single = 0b0001;  // edge 0->1 becomes edge 2 (1->0)
  reverseWinding(triangle, single);
  EXPECT_EQ(single, 0b0100);
}

TEST(ShellOrientation, SceneBuilderOrientsEvenUnderAMirroringScale) {
  SceneDescription description;
  description.materials = {Material{}};
  description.meshes.resize(2);
  description.meshes[1].scale = {-1, 1, 1};
  description.meshes[1].translate = {5, 0, 0};
  Mesh sphere = readMsh(test::mshFixture("sphere_v41_ascii.msh"));
  flipEvery(sphere, 2, 1);
  const std::size_t faceCount = sphere.faces.size();
  const Scene scene = buildScene(description, {sphere, sphere});
  ASSERT_EQ(scene.geometry.faces.size(), 2 * faceCount);
  int outward = 0;
  for (std::size_t f = 0; f < scene.geometry.faces.size(); ++f) {
    const Vec3d centre = f < faceCount ? Vec3d{0, 0, 0} : Vec3d{5, 0, 0};
    Vec3 centroid{0, 0, 0};
    for (int c = 0; c < 3; ++c)
      centroid += scene.geometry.positions[scene.geometry.faces[f].vertex[c]] * (1.0f / 3);
    outward += dot(scene.geometry.faceNormals[f], centroid - scene.geometry.toSceneSpace(centre)) > 0;
    EXPECT_EQ(scene.geometry.faceBoundsSolid[f], 1);
  }
  EXPECT_EQ(outward, static_cast<int>(scene.geometry.faces.size()));
}

}  // namespace
}  // namespace lancer
