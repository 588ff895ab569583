// The corners on each vertex: every corner once, in face order, the same on any number of threads,
// and with a filter, only the wanted vertices' rows.
#include <gtest/gtest.h>

#include "lancer/mesh/vertex_corners.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

TEST(VertexCorners, EveryCornerOnceInFaceOrderOnAnyThreadCount) {
  const test::Soup sphere = test::sphere(200, 250);  // ~50K vertices: up to 3 vertex ranges
  const std::size_t vertexCount = sphere.positions.size();
  ASSERT_EQ(vertexCountOf(sphere.faces, 3), vertexCount);
  const VertexCorners one = findVertexCorners(sphere.faces, vertexCount, 1);
  std::size_t corners = 0;
  for (const MeshFace& face : sphere.faces) corners += static_cast<std::size_t>(face.cornerCount());
  ASSERT_EQ(one.corner.size(), corners);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    for (std::uint32_t slot = one.rowStart[v]; slot < one.rowStart[v + 1]; ++slot) {
      const std::uint32_t code = one.corner[slot];
      EXPECT_EQ(sphere.faces[code >> 2].vertex[code & 3u], v);
      if (slot > one.rowStart[v]) {
        EXPECT_LT(one.corner[slot - 1], code);
      }
    }
  }
  for (const int threads : {2, 3, 8}) {
    const VertexCorners many = findVertexCorners(sphere.faces, vertexCount, threads);
    EXPECT_EQ(many.rowStart, one.rowStart) << threads;
    EXPECT_EQ(many.corner, one.corner) << threads;
  }
}

TEST(VertexCorners, OnlyTheWantedVerticesGetRows) {
  const test::Soup sphere = test::sphere(200, 250);
  const std::size_t vertexCount = sphere.positions.size();
  std::vector<std::uint8_t> wanted(vertexCount, 0);
  for (std::size_t v = 0; v < vertexCount; v += 7) wanted[v] = 1;
  const VertexCorners all = findVertexCorners(sphere.faces, vertexCount, 1);
  for (const int threads : {1, 3}) {
    const VertexCorners some = findVertexCorners(sphere.faces, vertexCount, threads, wanted);
    std::size_t kept = 0;
    for (std::size_t v = 0; v < vertexCount; ++v) {
      const std::uint32_t size = some.rowStart[v + 1] - some.rowStart[v];
      if (!wanted[v]) {
        EXPECT_EQ(size, 0u) << v;
        continue;
      }
      ASSERT_EQ(size, all.rowStart[v + 1] - all.rowStart[v]) << v;
      for (std::uint32_t k = 0; k < size; ++k)
        EXPECT_EQ(some.corner[some.rowStart[v] + k], all.corner[all.rowStart[v] + k]);
      kept += size;
    }
    EXPECT_EQ(some.corner.size(), kept);
  }
}

}  // namespace
}  // namespace lancer
