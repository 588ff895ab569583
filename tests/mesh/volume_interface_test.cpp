// Interfaces between volumes meshed together (tests/data/multimaterial, made by gmsh): the face two
// physical volumes share is kept once, belongs to both, and after scene set-up faces out of the
// volume it names as its inner side; surface elements on it merge into it; a mesh of one volume
// carries nothing more per face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene.hpp"
#include "support/files.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

std::string multimaterial(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/multimaterial/" + name;
}

double radius(const Vec3d& p) { return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z); }
double largestCoordinate(const Vec3d& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

// Cube [-1, 1]^3 ("Cube", tag 1) around a ball of radius 0.6 ("Ball", tag 2).
void expectCubeAroundBall(const Mesh& mesh, const std::string& file) {
  ASSERT_FALSE(mesh.volumeSides.empty()) << file;
  std::uint64_t interfaces = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const MeshFace& face = mesh.faces[f];
    if (mesh.volumeSides.isInterface(f)) {
      ++interfaces;
      const std::int32_t inner = mesh.facePhysicalTag[f], outer = mesh.volumeSides.outerPhysicalTag[f];
      ASSERT_TRUE((inner == 1 && outer == 2) || (inner == 2 && outer == 1)) << file << " face " << f;
      for (int c = 0; c < face.cornerCount(); ++c)
        ASSERT_NEAR(radius(mesh.worldPosition(face.vertex[c])), 0.6, 1e-3) << file << " face " << f;
    } else {
      ASSERT_EQ(mesh.facePhysicalTag[f], 1) << file << " face " << f;  // the cube's skin, in the cube's group
      for (int c = 0; c < face.cornerCount(); ++c)
        ASSERT_NEAR(largestCoordinate(mesh.worldPosition(face.vertex[c])), 1.0, 1e-9)
            << file << " face " << f;
    }
  }
  EXPECT_EQ(interfaces, mesh.source.interfaceFaces * (mesh.faceCount() / mesh.source.skinFaces)) << file;
  const MeshStats stats = computeMeshStats(mesh);
  // Every face once: the cube and the ball inscribed in its sphere (0.6% less area at this mesh size).
  EXPECT_NEAR(stats.area, 24.0 + 4 * std::numbers::pi * 0.36, 0.05) << file;
  EXPECT_LT(stats.area, 24.0 + 4 * std::numbers::pi * 0.36) << file;
}

TEST(VolumeInterface, SharedFacesOfTwoPhysicalVolumesAreKeptOnceInEveryFormat) {
  const Mesh v41 = readMsh(multimaterial("cube_sphere_v41.msh"));
  expectCubeAroundBall(v41, "v41");
  EXPECT_GT(v41.source.interfaceFaces, 500u);
  const Mesh v22 = readMsh(multimaterial("cube_sphere_v22.msh"));
  expectCubeAroundBall(v22, "v22");
  EXPECT_EQ(v22.faceCount(), v41.faceCount());
  EXPECT_EQ(v22.source.interfaceFaces, v41.source.interfaceFaces);
  // -save_all also writes every surface element, in no group: they are the same faces, not copies.
  const Mesh saveAll = readMsh(multimaterial("cube_sphere_saveall_v41.msh"));
  expectCubeAroundBall(saveAll, "save_all");
  EXPECT_EQ(saveAll.faceCount(), v41.faceCount());
  EXPECT_EQ(saveAll.source.interfaceSurfaceElementsMerged, v41.source.interfaceFaces);
  // Second order: each 6-node face split in four through its edge nodes, which gmsh put on the ball.
  const Mesh secondOrder = readMsh(multimaterial("cube_sphere_o2_v41.msh"));
  expectCubeAroundBall(secondOrder, "order 2");
  EXPECT_EQ(secondOrder.faceCount(), 4 * secondOrder.source.skinFaces);
}

// Without physical groups gmsh saves every element; the volumes are its two elementary entities,
// and the surface triangles on the ball are the interface, once.
TEST(VolumeInterface, VolumesInNoPhysicalGroupAreToldApartByTheirEntities) {
  const Mesh grouped = readMsh(multimaterial("cube_sphere_v41.msh"));
  const Mesh mesh = readMsh(multimaterial("cube_sphere_nogroups_v41.msh"));
  EXPECT_EQ(mesh.faceCount(), grouped.faceCount());
  EXPECT_EQ(mesh.source.interfaceFaces, grouped.source.interfaceFaces);
  EXPECT_EQ(mesh.source.interfaceSurfaceElementsMerged, grouped.source.interfaceFaces);
  const MeshStats stats = computeMeshStats(mesh);
  ASSERT_EQ(stats.interfaces.size(), 1u);
  EXPECT_EQ(stats.interfaces.begin()->first,
            (std::pair<std::int64_t, std::int64_t>{-3, -2}));  // entities 3, 2
  EXPECT_EQ(stats.interfaces.begin()->second, grouped.source.interfaceFaces);
}

TEST(VolumeInterface, HexahedraShareTheCylindersSide) {
  for (const char* file : {"box_cylinder_hex_v41.msh", "box_cylinder_hex27_v41.msh"}) {
    const Mesh mesh = readMsh(multimaterial(file));
    ASSERT_GT(mesh.source.interfaceFaces, 0u) << file;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      if (!mesh.volumeSides.isInterface(f)) continue;
      ASSERT_TRUE(mesh.faces[f].isQuad()) << file;
      for (int c = 0; c < 4; ++c) {
        const Vec3d p = mesh.worldPosition(mesh.faces[f].vertex[c]);
        ASSERT_NEAR(std::hypot(p.x, p.y), 0.6, 1e-3) << file << " face " << f;
      }
    }
  }
}

TEST(VolumeInterface, AMeshOfOneVolumeKeepsNoSides) {
  EXPECT_TRUE(readMsh(test::mshFixture("cube_tet4_v41_bin.msh")).volumeSides.empty());
  EXPECT_TRUE(readMsh(std::string(LANCER_TEST_DATA_DIR) + "/render/hollow_sphere.msh").volumeSides.empty());
}

// After scene set-up every volume face points out of the material its faceMaterial names: the ball's
// closed interface away from the centre, with the ball inside and the cube outside; on the slabs and
// the hexahedra, where interfaces meet the skin on edges of three faces, every face still bounds a
// solid, wound as its element.
SceneDescription twoMaterials(const char* first, const char* second) {
  SceneDescription d;
  Material a, b;
  a.name = first;
  b.name = second;
  d.materials = {a, b};
  d.meshes.resize(1);
  d.meshes[0].groupMaterials = {{first, 0, {}}, {second, 1, {}}};
  return d;
}

Vec3 centroid(const Scene& scene, std::size_t f) {
  Vec3 sum{0, 0, 0};
  const MeshFace& face = scene.geometry.faces[f];
  for (int c = 0; c < face.cornerCount(); ++c) sum += scene.geometry.positions[face.vertex[c]];
  return sum * (1.0f / static_cast<float>(face.cornerCount()));
}

TEST(VolumeInterface, ClosedInterfacesFaceOutOfTheVolumeTheyEnclose) {
  const Scene scene =
      test::sceneFromMeshes(twoMaterials("Cube", "Ball"), {readMsh(multimaterial("cube_sphere_v41.msh"))});
  ASSERT_EQ(scene.appearance.faceOuterMaterial.size(), scene.geometry.faces.size());
  std::size_t interfaces = 0;
  for (std::size_t f = 0; f < scene.geometry.faces.size(); ++f) {
    ASSERT_TRUE(scene.geometry.faceBoundsSolid[f]) << f;
    const Vec3 outward = centroid(scene, f) - scene.geometry.toSceneSpace({0, 0, 0});
    ASSERT_GT(dot(scene.geometry.faceNormals[f], outward), 0.0f) << f;
    if (scene.appearance.faceOuterMaterial[f] == SceneAppearance::kNoMaterial) {
      ASSERT_EQ(scene.appearance.faceMaterial[f], 0u) << f;
      continue;
    }
    ++interfaces;
    ASSERT_EQ(scene.appearance.faceMaterial[f], 1u) << f;       // the ball behind
    ASSERT_EQ(scene.appearance.faceOuterMaterial[f], 0u) << f;  // the cube in front
  }
  EXPECT_GT(interfaces, 500u);
}

TEST(VolumeInterface, FacesOnNonManifoldRimsBoundSolidsWoundOutOfTheirVolume) {
  const Scene slabs = test::sceneFromMeshes(twoMaterials("Glass", "Water"),
                                            {readMsh(multimaterial("glass_water_slabs_v41.msh"))});
  for (std::size_t f = 0; f < slabs.geometry.faces.size(); ++f) {
    ASSERT_TRUE(slabs.geometry.faceBoundsSolid[f]) << f;
    // Glass is y in [0, 1], water y in [-1, 0]: a face points away from its own slab's middle.
    const float middle = slabs.appearance.faceMaterial[f] == 0 ? 0.5f : -0.5f;
    const Vec3 fromMiddle = centroid(slabs, f) - slabs.geometry.toSceneSpace({0, middle, 0});
    ASSERT_GT(dot(slabs.geometry.faceNormals[f], fromMiddle), 0.0f) << f;
    if (slabs.appearance.faceOuterMaterial[f] != SceneAppearance::kNoMaterial) {
      ASSERT_NE(slabs.appearance.faceOuterMaterial[f], slabs.appearance.faceMaterial[f]) << f;
    }
  }
  const Scene hexes = test::sceneFromMeshes(twoMaterials("Box", "Cylinder"),
                                            {readMsh(multimaterial("box_cylinder_hex_v41.msh"))});
  for (std::size_t f = 0; f < hexes.geometry.faces.size(); ++f) {
    ASSERT_TRUE(hexes.geometry.faceBoundsSolid[f]) << f;
    if (hexes.appearance.faceOuterMaterial[f] == SceneAppearance::kNoMaterial) continue;
    // On the cylinder's side: out of the cylinder means away from the axis, out of the box towards it.
    Vec3 radial = centroid(hexes, f) - hexes.geometry.toSceneSpace({0, 0, 0});
    radial.z = 0;
    const float sign = hexes.appearance.faceMaterial[f] == 1 ? 1.0f : -1.0f;
    ASSERT_GT(sign * dot(hexes.geometry.faceNormals[f], radial), 0.0f) << f;
  }
}

}  // namespace
}  // namespace lancer
