// Watertightness: on a closed gmsh mesh, a ray from inside must hit something, also when it is
// aimed exactly at a shared edge or vertex, where a triangle test that is not watertight lets rays
// slip between the two triangles (a background pixel seen through a closed surface).
#include <gtest/gtest.h>

#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

struct ClosedMesh {
  std::string name;
  Vec3 inside;  // a point inside the closed surface, in the mesh's local frame
};

TEST(Watertight, RaysFromInsideAimedAtEdgesAndVerticesAlwaysHit) {
  // Fine gmsh spheres (render fixtures) and a cube volume's skin: closed shells of many shapes.
  for (const std::string file : {"render/sphere_fine.msh", "render/ball.msh", "msh/cube_tet4_v41_bin.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/" + file);
    const NaiveAccel naive(mesh.positions, mesh.faces);
    const KdTree tree = KdTree::buildSah(mesh.positions, mesh.faces);
    int rays = 0, naiveMisses = 0, treeMisses = 0;
    for (const Ray& ray : test::raysAtCornersAndEdges(mesh.positions, mesh.faces)) {
      Hit hit;
      // Brute force on every 8th ray only: it shares the triangle test and costs 8K tests a ray.
      if (rays++ % 8 == 0) naiveMisses += !naive.intersect(ray, 0.0f, 2.0f, hit);
      treeMisses += !tree.intersect(ray, 0.0f, 2.0f, hit);
      treeMisses += !tree.occluded(ray, 0.0f, 2.0f);
    }
    EXPECT_EQ(naiveMisses, 0) << "of " << rays / 8 << " rays";
    EXPECT_EQ(treeMisses, 0) << "of " << rays << " rays";
  }
}

}  // namespace
}  // namespace lancer
