// Scene preparation gives the same bytes on any number of threads: the face shells' edge table
// equals a plain sort of every face's edges on 1, 2 and 5 threads, and corner normals and the whole scene
// agree between 1 and 5 threads on meshes big enough to be cut into many chunks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "lancer/mesh/face_geometry.hpp"
#include "lancer/mesh/face_shells.hpp"
#include "lancer/mesh/mesh_from_elements.hpp"
#include "lancer/mesh/vertex_normals.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/util/parallel_for.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

// A UV sphere of ~100K vertices (quads, triangle fans at the poles), with two physical groups, so
// corner normals split along the group boundary and at the poles' creases.
struct TaggedSoup {
  test::Soup soup;
  std::vector<std::int32_t> tags;
};

TaggedSoup bigSphere() {
  TaggedSoup mesh{test::sphere(300, 330), {}};
  for (std::size_t f = 0; f < mesh.soup.faces.size(); ++f) mesh.tags.push_back(f % 7 == 0 ? 2 : 1);
  return mesh;
}

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(ParallelPreparation, ChunksCoverTheRangeOnceWhateverTheThreads) {
  for (const std::size_t count : {0u, 1u, 1000u, 100000u, 123457u}) {
    for (const int threads : {1, 2, 7}) {
      std::vector<int> seen(count, 0);
      parallelFor(count, threads, 1000, [&](std::size_t i) { ++seen[i]; });
      EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }))
          << count << " " << threads;
    }
  }
}

TEST(ParallelPreparation, AnExceptionInAChunkReachesTheCaller) {
  EXPECT_THROW(parallelFor(100000, 3, 1000,
                           [](std::size_t i) {
                             if (i == 54321) throw std::runtime_error("x");
                           }),
               std::runtime_error);
}

TEST(ParallelPreparation, FaceShellEdgesEqualAStableSortOfAllEdges) {
  TaggedSoup mesh = bigSphere();
  // Some faces turned: the shells are walked over the sorted table (an agreeing one needs none).
  std::uint8_t unusedMask = kAllEdges;
  for (std::size_t f = 0; f < mesh.soup.faces.size(); f += 97) reverseWinding(mesh.soup.faces[f], unusedMask);
  struct Edge {
    std::uint64_t key;  // smaller vertex << 32 | larger
    std::uint32_t face;
    bool forward;
  };
  std::vector<Edge> expected;
  for (std::size_t f = 0; f < mesh.soup.faces.size(); ++f) {
    const MeshFace& face = mesh.soup.faces[f];
    const int n = face.cornerCount();
    for (int c = 0; c < n; ++c) {
      const std::uint32_t a = face.vertex[c], b = face.vertex[(c + 1) % n];
      expected.push_back(
          {(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), static_cast<std::uint32_t>(f), a < b});
    }
  }
  std::stable_sort(expected.begin(), expected.end(),
                   [](const Edge& x, const Edge& y) { return x.key < y.key; });
  const FaceShells one = findFaceShells(mesh.soup.faces, 1);
  for (const int threads : {1, 2, 5}) {
    const FaceShells shells = findFaceShells(mesh.soup.faces, threads);
    ASSERT_EQ(shells.edges.size(), expected.size());
    ASSERT_EQ(shells.edgeStart.back(), expected.size());
    std::uint64_t smaller = 0;  // the bucket of edge i
    for (std::size_t i = 0; i < expected.size(); ++i) {
      while (shells.edgeStart[smaller + 1] <= i) ++smaller;
      ASSERT_EQ(smaller << 32 | shells.edges[i].larger, expected[i].key) << i;
      ASSERT_EQ(shells.edges[i].face(), expected[i].face) << i;
      ASSERT_EQ(shells.edges[i].forward(), expected[i].forward) << i;
    }
    EXPECT_TRUE(sameBytes(shells.shellOfFace, one.shellOfFace));
    EXPECT_TRUE(sameBytes(shells.flip, one.flip));
    EXPECT_TRUE(sameBytes(shells.orientable, one.orientable));
  }
}

// The sphere as gmsh-like input for the assembler: points in double with unused points between
// them (so vertices are renumbered), and every 1000th face made degenerate (so faces are dropped).
struct AssemblyInput {
  std::vector<Vec3d> points;
  SurfaceFacesInput faces;
};

AssemblyInput assemblyInput() {
  const TaggedSoup sphere = bigSphere();
  AssemblyInput input;
  for (const Vec3& p : sphere.soup.positions) {
    input.points.push_back(toDouble(p) + Vec3d{10, 20, 30});
    input.points.push_back(Vec3d{1e3, 1e3, 1e3});  // no face uses it
  }
  for (std::size_t f = 0; f < sphere.soup.faces.size(); ++f) {
    MeshFace face = sphere.soup.faces[f];
    for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] *= 2;
    if (f % 1000 == 0)
      for (int c = 1; c < face.cornerCount(); ++c) face.vertex[c] = face.vertex[0];
    input.faces.faces.push_back(face);
    input.faces.physical.push_back(sphere.tags[f]);
    input.faces.entity.push_back(sphere.tags[f] + 10);
  }
  return input;
}

void expectSameMesh(const Mesh& a, const Mesh& b) {
  EXPECT_TRUE(sameBytes(a.positions, b.positions));
  EXPECT_TRUE(sameBytes(a.faces, b.faces));
  EXPECT_TRUE(sameBytes(a.facePhysicalTag, b.facePhysicalTag));
  EXPECT_TRUE(sameBytes(a.faceEntityTag, b.faceEntityTag));
  EXPECT_TRUE(sameBytes(a.faceEdgeMask, b.faceEdgeMask));
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.source.degenerateFacesDropped, b.source.degenerateFacesDropped);
  EXPECT_EQ(a.physicalGroups.size(), b.physicalGroups.size());
}

TEST(ParallelPreparation, AssembledMeshesAreTheSameOnOneAndFiveThreadsAndAsElementByElement) {
  const AssemblyInput input = assemblyInput();
  const Mesh one = meshFromFaces(input.points, input.faces, {}, "sphere", 1);
  const Mesh five = meshFromFaces(input.points, input.faces, {}, "sphere", 5);
  ASSERT_GT(one.faces.size(), 90000u);                       // many chunks of the parallel passes
  EXPECT_EQ(one.positions.size(), input.points.size() / 2);  // the unused points are gone
  EXPECT_EQ(one.source.degenerateFacesDropped, (input.faces.faces.size() + 999) / 1000);
  expectSameMesh(one, five);
  // The element path (the reader's, one addElement per face) gives the same mesh.
  std::vector<std::uint32_t> nodes;
  std::vector<ElementBlock> blocks;
  std::vector<std::size_t> starts;
  for (std::size_t f = 0; f < input.faces.faces.size(); ++f) {
    const MeshFace& face = input.faces.faces[f];
    starts.push_back(nodes.size());
    nodes.insert(nodes.end(), face.vertex, face.vertex + face.cornerCount());
  }
  for (std::size_t f = 0; f < input.faces.faces.size(); ++f) {
    const std::size_t end = f + 1 < starts.size() ? starts[f + 1] : nodes.size();
    blocks.push_back({input.faces.faces[f].isQuad() ? 3 : 2,
                      2,
                      input.faces.physical[f],
                      input.faces.entity[f],
                      std::span<const std::uint32_t>(nodes.data() + starts[f], end - starts[f]),
                      {}});
  }
  expectSameMesh(one, meshFromElements(input.points, blocks, {}, "sphere"));
}

TEST(ParallelPreparation, CornerNormalsAreTheSameOnOneAndFiveThreads) {
  const TaggedSoup mesh = bigSphere();
  ASSERT_GT(mesh.soup.positions.size(), 60000u);  // several chunks of the parallel loops
  const CornerNormals one = computeCornerNormals(mesh.soup.positions, mesh.soup.faces, mesh.tags, 30.0f, 1);
  const CornerNormals five = computeCornerNormals(mesh.soup.positions, mesh.soup.faces, mesh.tags, 30.0f, 5);
  EXPECT_TRUE(sameBytes(one.normals, five.normals));
  EXPECT_TRUE(sameBytes(one.faceCorner, five.faceCorner));
  // The group boundary and the poles split some vertices: more normals than vertices.
  EXPECT_GT(one.normals.size(), mesh.soup.positions.size());
  // Every corner points at its own vertex's normal (chunks' indices joined right): on a fine
  // sphere that is nearly the face's normal, and a normal of another chunk's vertex would not be.
  std::size_t far = 0;
  for (std::size_t f = 0; f < mesh.soup.faces.size(); ++f) {
    const MeshFace& face = mesh.soup.faces[f];
    const Vec3 n = faceNormal(mesh.soup.positions, face);
    for (int c = 0; c < face.cornerCount(); ++c) far += dot(n, one.normals[one.faceCorner[f][c]]) < 0.9f;
  }
  EXPECT_EQ(far, 0u);
}

TEST(ParallelPreparation, BuiltScenesAreTheSameOnOneAndFiveThreads) {
  const TaggedSoup sphere = bigSphere();
  Mesh mesh;
  for (const Vec3& p : sphere.soup.positions) mesh.positions.push_back(p);
  mesh.faces = sphere.soup.faces;
  mesh.facePhysicalTag = sphere.tags;
  mesh.faceEntityTag.assign(mesh.faces.size(), 1);
  SceneDescription description;
  description.materials.push_back(Material{});
  description.meshes.push_back(MeshInstance{});
  const Scene one = buildScene(description, {mesh}, 1);
  const Scene five = buildScene(description, {mesh}, 5);
  EXPECT_TRUE(sameBytes(one.geometry.positions, five.geometry.positions));
  EXPECT_TRUE(sameBytes(one.geometry.faces, five.geometry.faces));
  EXPECT_TRUE(sameBytes(one.geometry.faceNormals, five.geometry.faceNormals));
  EXPECT_TRUE(sameBytes(one.geometry.cornerNormals.normals, five.geometry.cornerNormals.normals));
  EXPECT_TRUE(sameBytes(one.geometry.cornerNormals.faceCorner, five.geometry.cornerNormals.faceCorner));
  EXPECT_TRUE(sameBytes(one.geometry.faceBoundsSolid, five.geometry.faceBoundsSolid));
  EXPECT_TRUE(sameBytes(one.appearance.faceMaterial, five.appearance.faceMaterial));
}

}  // namespace
}  // namespace lancer
