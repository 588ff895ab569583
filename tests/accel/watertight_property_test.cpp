// Watertightness: on a closed gmsh mesh, a ray from inside must hit something, also when it is
// aimed exactly at a shared edge or vertex, where a triangle test that is not watertight lets rays
// slip between the two triangles (a background pixel seen through a closed surface).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "lancer/mesh/msh_reader.hpp"

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
    Aabb box;
    for (const Vec3& p : mesh.positions) box.extend(p);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
    int rays = 0, naiveMisses = 0, treeMisses = 0;
    for (const MeshFace& face : mesh.faces) {
      for (int c = 0; c < face.cornerCount(); ++c) {
        const Vec3 a = mesh.positions[face.vertex[c]];
        const Vec3 b = mesh.positions[face.vertex[(c + 1) % face.cornerCount()]];
        // Origins near the centre (each ray from its own), targets on a vertex and on the edge.
        for (const float s : {0.0f, 0.5f, 0.25f}) {
          const Vec3 origin = box.center() + box.extent() * Vec3{jitter(rng), jitter(rng), jitter(rng)};
          const Vec3 target = a + (b - a) * s;
          const Ray ray(origin, target - origin);
          Hit hit;
          // Brute force on every 8th ray only: it shares the triangle test and costs 8K tests a ray.
          if (rays++ % 8 == 0) naiveMisses += !naive.intersect(ray, 0.0f, 2.0f, hit);
          treeMisses += !tree.intersect(ray, 0.0f, 2.0f, hit);
          treeMisses += !tree.occluded(ray, 0.0f, 2.0f);
        }
      }
    }
    EXPECT_EQ(naiveMisses, 0) << "of " << rays / 8 << " rays";
    EXPECT_EQ(treeMisses, 0) << "of " << rays << " rays";
  }
}

}  // namespace
}  // namespace lancer
