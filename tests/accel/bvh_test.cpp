// The BVH's own guarantees (its answers against brute force on rays aimed at kd split planes are in
// kd_tree_property_test.cpp and packet_query_property_test.cpp, with every accelerator): rays aimed
// at its own boxes, the layout's invariants, the same tree on any thread count, refit answering as a
// rebuild, the rule for when a rebuild pays, and rays walked several in flight answering as single rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

using test::Soup;

Soup fixture(const std::string& name) {
  const Mesh mesh = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/" + name);
  return Soup{mesh.positions, mesh.faces};
}

BvhBuildOptions onThreads(int threads) {
  BvhBuildOptions options;
  options.threads = threads;
  return options;
}

TEST(Bvh, EmptyMeshHasNoHitsAndOneTriangleIsFound) {
  const Bvh empty = Bvh::build({}, {}, onThreads(1));
  Hit hit;
  EXPECT_FALSE(empty.intersect(Ray({0, 0, 1}, {0, 0, -1}), 0.0f, 1e30f, hit));
  EXPECT_FALSE(empty.occluded(Ray({0, 0, 1}, {0, 0, -1}), 0.0f, 1e30f));
  Soup soup;
  soup.triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  const Bvh one = Bvh::build(soup.positions, soup.faces, onThreads(1));
  ASSERT_TRUE(one.intersect(Ray({0.25f, 0.25f, 1}, {0, 0, -1}), 0.0f, 1e30f, hit));
  EXPECT_EQ(hit.face, 0u);
  EXPECT_EQ(hit.t, 1.0f);
  EXPECT_FALSE(one.intersect(Ray({0.25f, 0.25f, 1}, {0, 0, -1}), 0.0f, 1.0f, hit)) << "open interval";
  EXPECT_EQ(one.stats().kind, "bvh");
  EXPECT_EQ(one.stats().triangles, 1u);
}

// A mesh of slivers only has no tree: its triangles are all kept beside it, as they are.
TEST(Bvh, AMeshOfSliversOnlyKeepsThemAll) {
  Soup soup;
  soup.triangle({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
  soup.triangle({0, 1, 0}, {0, 2, 0}, {0, 3, 0});
  const Bvh bvh = Bvh::build(soup.positions, soup.faces, onThreads(2));
  ASSERT_EQ(bvh.slivers().size(), 2u);
  for (std::uint32_t f = 0; f < 2; ++f) {
    const PackedTriangle& t = bvh.slivers()[f];
    EXPECT_EQ(t.face, f);
    EXPECT_EQ(t.v0, soup.positions[soup.faces[f].vertex[0]]);
    EXPECT_EQ(t.v1, soup.positions[soup.faces[f].vertex[1]]);
    EXPECT_EQ(t.v2, soup.positions[soup.faces[f].vertex[2]]);
  }
  EXPECT_EQ(bvh.stats().triangles, 2u);
}

// Every tree face in exactly one leaf of at most eight triangles; a quad's halves side by side in one
// leaf, (0,1,2) first; each triangle's corners the face's own positions, every leaf vertex used and
// listed once; children's boxes hold their triangles; leaves lie in their array one after another.
TEST(Bvh, LayoutInvariants) {
  for (const char* name : {"accel/quad_box.msh", "accel/gmsh_tutorial_t5.msh"}) {
    SCOPED_TRACE(name);
    const Soup soup = fixture(name);
    const Bvh bvh = Bvh::build(soup.positions, soup.faces, onThreads(2));
    std::vector<int> seen(soup.faces.size(), 0);
    std::size_t triangles = 0, words = 0;
    for (const BvhNode& node : bvh.nodes()) {
      for (int k = 0; k < BvhNode::kWidth; ++k) {
        const std::uint32_t child = node.child[k];
        if (child == BvhNode::kEmpty || !BvhNode::isLeaf(child)) continue;
        const bvh::BvhLeaf leaf = bvh.leaf(child);
        const std::uint32_t count = leaf.count();
        ASSERT_LE(count, BvhNode::kMaxLeafTriangles);
        ASSERT_LE(leaf.vertexCount(), 3 * count);
        ASSERT_LE(BvhNode::leafFirst(child) + bvh::BvhLeaf::words(count, leaf.vertexCount()),
                  bvh.leafWords().size());
        triangles += count;
        words += bvh::BvhLeaf::words(count, leaf.vertexCount());
        std::vector<int> used(leaf.vertexCount(), 0);
        for (std::uint32_t i = 0; i < count; ++i) {
          const PackedTriangle tri = leaf.triangle(i);
          for (int c = 0; c < 3; ++c) ++used[leaf.corner(i, c)];
          for (const Vec3& p : {tri.v0, tri.v1, tri.v2}) {
            for (int a = 0; a < 3; ++a) {
              EXPECT_GE(p[a], node.lower[a][k]);
              EXPECT_LE(p[a], node.upper[a][k]);
            }
          }
          ASSERT_LT(tri.face, soup.faces.size());
          const MeshFace& face = soup.faces[tri.face];
          const bool second = i > 0 && leaf.face(i - 1) == tri.face;
          if (!second) ++seen[tri.face];
          if (face.isQuad() && !second) {
            ASSERT_LT(i + 1, count) << "a quad's halves share a leaf";
            EXPECT_EQ(leaf.face(i + 1), tri.face);
          }
          const int h = second ? 1 : 0;
          EXPECT_EQ(tri.v0, soup.positions[face.vertex[0]]);
          EXPECT_EQ(tri.v1, soup.positions[face.vertex[1 + h]]);
          EXPECT_EQ(tri.v2, soup.positions[face.vertex[2 + h]]);
        }
        for (int n : used) EXPECT_GT(n, 0) << "a leaf vertex no corner uses";
        for (std::uint32_t v = 0; v < leaf.vertexCount(); ++v) {
          for (std::uint32_t w = v + 1; w < leaf.vertexCount(); ++w) {
            const Vec3 a = leaf.vertex(v), b = leaf.vertex(w);
            // Two leaf vertices may only share a position as two mesh vertices do.
            if (a == b) {
              EXPECT_TRUE(std::count(soup.positions.begin(), soup.positions.end(), a) > 1);
            }
          }
        }
      }
    }
    for (int count : seen) EXPECT_EQ(count, 1);
    EXPECT_EQ(bvh.stats().triangleReferences, triangles);
    EXPECT_EQ(words + bvh::kLeafTailWords, bvh.leafWords().size()) << "leaves packed one after another";
  }
}

TEST(Bvh, SameTreeByteForByteOnOneToFourThreads) {
  std::mt19937 rng(3);
  Soup soup = test::randomSoup(rng, 20000);
  const Soup quads = fixture("accel/quad_box.msh");
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  soup.positions.insert(soup.positions.end(), quads.positions.begin(), quads.positions.end());
  for (MeshFace face : quads.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += base;
    soup.faces.push_back(face);
  }
  auto bytesOf = [](const Bvh& bvh) {
    std::string bytes(reinterpret_cast<const char*>(bvh.nodes().data()), bvh.nodes().size_bytes());
    bytes.append(reinterpret_cast<const char*>(bvh.leafWords().data()), bvh.leafWords().size_bytes());
    return bytes;
  };
  // Clusters of 512 (the default) and of 4 (thousands of clusters: several batches of them, a deep
  // top over them).
  for (std::uint32_t clusterSize : {512u, 4u}) {
    BvhBuildOptions serial = onThreads(1);
    serial.maxClusterReferences = clusterSize;
    const std::string one = bytesOf(Bvh::build(soup.positions, soup.faces, serial));
    for (int threads : {2, 3, 4}) {
      SCOPED_TRACE(std::to_string(threads) + " threads, clusters of " + std::to_string(clusterSize));
      BvhBuildOptions options = serial;
      options.threads = threads;
      EXPECT_TRUE(bytesOf(Bvh::build(soup.positions, soup.faces, options)) == one);
    }
  }
}

// A smooth warp of every vertex (a deformed time step): same faces, moved nodes.
std::vector<Vec3> warped(const std::vector<Vec3>& positions, float amount) {
  std::vector<Vec3> out = positions;
  for (Vec3& p : out) {
    p = p + Vec3{std::sin(3.0f * p.y), std::sin(2.0f * p.z + 1.0f), std::cos(2.5f * p.x)} * amount;
  }
  return out;
}

TEST(Bvh, RefitAnswersAsARebuildAndBruteForce) {
  for (const std::string name : {"accel/holed_block.msh", "accel/quad_box.msh"}) {
    SCOPED_TRACE(name);
    const Soup soup = fixture(name);
    Aabb box;
    for (const Vec3& p : soup.positions) box.extend(p);
    Bvh refitted = Bvh::build(soup.positions, soup.faces, onThreads(2));
    ASSERT_TRUE(refitted.refit(soup.positions, soup.faces, 2));
    EXPECT_NEAR(refitted.sahGrowth(), 1.0, 1e-9) << "refit in place changes nothing";
    const std::vector<Vec3> moved = warped(soup.positions, 0.05f * maxComponent(box.extent()));
    ASSERT_TRUE(refitted.refit(moved, soup.faces, 3));
    const Bvh rebuilt = Bvh::build(moved, soup.faces, onThreads(1));
    const NaiveAccel naive(moved, soup.faces);
    const Soup movedSoup{moved, soup.faces};
    const KdTree planes = KdTree::buildSah(moved, soup.faces);
    std::mt19937 rng(9);
    int differences = 0, hits = 0;
    for (const test::TestRay& r : test::adversarialRays(movedSoup, planes, rng, 4000)) {
      Hit a, b, c;
      const bool hitA = refitted.intersect(r.ray, r.tMin, r.tMax, a);
      const bool hitB = rebuilt.intersect(r.ray, r.tMin, r.tMax, b);
      const bool hitC = naive.intersect(r.ray, r.tMin, r.tMax, c);
      hits += hitA;
      const bool same = hitA == hitB && hitA == hitC &&
                        (!hitA || (test::sameBits(a, b) && a.face == c.face)) &&
                        refitted.occluded(r.ray, r.tMin, r.tMax) == rebuilt.occluded(r.ray, r.tMin, r.tMax);
      if (!same && ++differences <= 5) ADD_FAILURE() << "refit " << a.face << " rebuild " << b.face;
    }
    EXPECT_EQ(differences, 0);
    EXPECT_GT(hits, 1000);
    EXPECT_GT(refitted.sahGrowth(), 0.5);
  }
}

// The boxes of every child of every node (the BVH's planes, as the kd-tree's split planes are the
// kd-tree's).
std::vector<Aabb> childBoxes(const Bvh& bvh) {
  std::vector<Aabb> boxes;
  for (const BvhNode& node : bvh.nodes()) {
    for (int k = 0; k < BvhNode::kWidth && node.child[k] != BvhNode::kEmpty; ++k) {
      boxes.push_back({{node.lower[0][k], node.lower[1][k], node.lower[2][k]},
                       {node.upper[0][k], node.upper[1][k], node.upper[2][k]}});
    }
  }
  return boxes;
}

// Packets of eight rays aimed at the BVH's own boxes: from inside a box in random directions, from
// outside at a box's eight corners, lying in a box's face plane parallel to it, along a box's edges,
// and with intervals that end on a corner. Every lane of every query, packet or single, with and
// without a filter, equals brute force (the hit bit for bit).
TEST(Bvh, RaysAtItsOwnBoxesMatchBruteForce) {
  for (const std::string name :
       {"accel/holed_block.msh", "accel/quad_box.msh", "accel/gmsh_tutorial_t5.msh"}) {
    SCOPED_TRACE(name);
    const Soup soup = fixture(name);
    const Bvh bvh = Bvh::build(soup.positions, soup.faces, onThreads(2));
    const NaiveAccel naive(soup.positions, soup.faces);
    const std::vector<Aabb> boxes = childBoxes(bvh);
    ASSERT_GT(boxes.size(), 100u);
    Aabb scene;
    for (const Vec3& p : soup.positions) scene.extend(p);
    const Vec3 pad = scene.extent() * 0.5f;
    std::mt19937 rng(23);
    std::uniform_int_distribution<std::size_t> anyBox(0, boxes.size() - 1);
    // Refuses every third face: the filtered queries see through them.
    const HitFilter everyThird{
        nullptr, [](const void*, const Ray&, std::uint32_t face, float) { return face % 3 != 0; }};
    int differences = 0, hits = 0, rays = 0;
    for (int p = 0; p < 600; ++p) {
      const Aabb& box = boxes[anyBox(rng)];
      const int variant = p % 5;
      RayPacket packet;
      for (int i = 0; i < kPacketSize; ++i) {
        const Vec3 corner{i & 1 ? box.upper.x : box.lower.x, i & 2 ? box.upper.y : box.lower.y,
                          i & 4 ? box.upper.z : box.lower.z};
        Vec3 origin = test::randomPoint(rng, scene.lower - pad, scene.upper + pad), direction;
        packet.tMin[i] = 0.0f;
        packet.tMax[i] = 1e30f;
        if (variant == 0) {  // inside the box
          origin = test::randomPoint(rng, box.lower, box.upper);
          direction = test::randomDirection(rng);
        } else if (variant == 1) {  // at a corner, the interval ending on it for half the lanes
          direction = corner - origin;
          if (i % 2 == 1) packet.tMax[i] = 1.0f;
        } else if (variant == 2) {  // in a face plane, parallel to it
          const int axis = static_cast<int>(rng() % 3);
          origin[axis] = i % 2 == 0 ? box.lower[axis] : box.upper[axis];
          direction = test::randomDirection(rng);
          direction[axis] = 0.0f;
          if (dot(direction, direction) == 0.0f) direction[(axis + 1) % 3] = 1.0f;
        } else if (variant == 3) {  // along an edge, axis-parallel
          const int axis = static_cast<int>(rng() % 3);
          origin = corner;
          origin[axis] = i % 2 == 0 ? scene.lower[axis] - pad[axis] : scene.upper[axis] + pad[axis];
          direction = Vec3{0, 0, 0};
          direction[axis] = i % 2 == 0 ? 1.0f : -1.0f;
        } else {  // a coherent bundle through the box, starting past its near side
          origin = box.lower - pad * 0.25f;
          direction = test::randomPoint(rng, box.lower, box.upper) - origin;
          packet.tMin[i] = 0.5f;
        }
        new (&packet.ray[i]) Ray(origin, direction);
      }
      std::array<Hit, kPacketSize> packetHits, filteredHits;
      const std::uint32_t hitLanes = bvh.intersect(packet, kAllLanes, packetHits);
      const std::uint32_t occludedLanes = bvh.occluded(packet, kAllLanes);
      const std::uint32_t filteredLanes = bvh.intersect(packet, kAllLanes, everyThird, filteredHits);
      const std::uint32_t filteredOccluded = bvh.occluded(packet, kAllLanes, everyThird);
      for (int i = 0; i < kPacketSize; ++i) {
        const Ray& ray = packet.ray[i];
        const float tMin = packet.tMin[i], tMax = packet.tMax[i];
        Hit expected, single, expectedFiltered;
        const bool expectHit = naive.intersect(ray, tMin, tMax, expected);
        const bool expectFiltered = naive.intersect(ray, tMin, tMax, everyThird, expectedFiltered);
        hits += expectHit;
        ++rays;
        bool same =
            bvh.intersect(ray, tMin, tMax, single) == expectHit && ((hitLanes >> i & 1u) != 0) == expectHit;
        same = same &&
               (!expectHit || (test::sameBits(single, expected) && test::sameBits(packetHits[i], expected)));
        same = same && ((filteredLanes >> i & 1u) != 0) == expectFiltered &&
               (!expectFiltered || test::sameBits(filteredHits[i], expectedFiltered));
        const bool expectOccluded = naive.occluded(ray, tMin, tMax);
        same = same && bvh.occluded(ray, tMin, tMax) == expectOccluded &&
               ((occludedLanes >> i & 1u) != 0) == expectOccluded &&
               ((filteredOccluded >> i & 1u) != 0) == naive.occluded(ray, tMin, tMax, everyThird);
        if (!same && ++differences <= 5) {
          ADD_FAILURE() << "packet " << p << " lane " << i << " (variant " << variant << "): brute force "
                        << (expectHit ? std::to_string(expected.face) : "miss");
        }
      }
    }
    EXPECT_EQ(differences, 0) << "of " << rays << " rays";
    EXPECT_GT(hits, rays / 4);
  }
}

TEST(Bvh, RefitRefusesWhatItCannotKeepExact) {
  Soup soup;
  soup.triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  soup.triangle({2, 0, 0}, {3, 0, 0}, {2, 1, 0});
  Bvh bvh = Bvh::build(soup.positions, soup.faces, onThreads(1));
  std::vector<Vec3> flattened = soup.positions;
  for (int c = 0; c < 3; ++c)  // the first triangle collapses onto a line: a sliver
    flattened[soup.faces[0].vertex[c]] = {float(c), 0.0f, 0.0f};
  EXPECT_FALSE(bvh.refit(flattened, soup.faces));
  EXPECT_FALSE(bvh.refit(std::vector<Vec3>(2), soup.faces)) << "too few vertices";
}

TEST(Bvh, AcceleratorUpdateRefitsTheBvhAndRebuildsTheRest) {
  const Soup soup = fixture("accel/holed_block.msh");
  Aabb box;
  for (const Vec3& p : soup.positions) box.extend(p);
  const std::vector<Vec3> moved = warped(soup.positions, 0.02f * maxComponent(box.extent()));
  Accelerator bvh = Accelerator::build(soup.positions, soup.faces, AccelKind::Bvh);
  EXPECT_TRUE(bvh.update(moved, soup.faces));
  Accelerator kd = Accelerator::build(soup.positions, soup.faces, AccelKind::KdTreeSah);
  EXPECT_FALSE(kd.update(moved, soup.faces));
  // A warp that scrambles the vertices makes the kept tree much worse: a rebuild pays.
  std::vector<Vec3> scrambled = soup.positions;
  std::mt19937 rng(4);
  std::shuffle(scrambled.begin(), scrambled.end(), rng);
  Bvh kept = Bvh::build(soup.positions, soup.faces, onThreads(1));
  if (kept.refit(scrambled, soup.faces)) {
    EXPECT_TRUE(kept.rebuildPays()) << kept.sahGrowth();
  }
  const NaiveAccel naive(moved, soup.faces);
  std::mt19937 rays(5);
  for (int i = 0; i < 500; ++i) {
    const Ray ray(test::randomPoint(rays, box.lower, box.upper), test::randomDirection(rays));
    Hit expected, a, b;
    ASSERT_EQ(naive.intersect(ray, 0.0f, 1e30f, expected), bvh.intersect(ray, 0.0f, 1e30f, a));
    ASSERT_EQ(naive.intersect(ray, 0.0f, 1e30f, expected), kd.intersect(ray, 0.0f, 1e30f, b));
    EXPECT_EQ(a.face, expected.face);
    EXPECT_EQ(b.face, expected.face);
  }
}

// Rays in flight: each answer is the single ray's, to the bit for closest hits, with and without a
// filter, for batches shorter than, equal to and longer than the rays in flight, rays that miss the
// scene box among them, and per-ray ends of the interval (some before the first hit).
TEST(Bvh, RaysInFlightAnswerAsSingleRays) {
  std::mt19937 rng(11);
  Soup soup = test::randomSoup(rng, 3000);
  const Soup quads = fixture("accel/quad_box.msh");
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  soup.positions.insert(soup.positions.end(), quads.positions.begin(), quads.positions.end());
  for (MeshFace face : quads.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += base;
    soup.faces.push_back(face);
  }
  const Bvh bvh = Bvh::build(soup.positions, soup.faces, onThreads(2));
  std::vector<Ray> rays;
  std::vector<float> tMax;
  std::uniform_real_distribution<float> length(0.0f, 2.0f);
  for (int i = 0; i < 600; ++i) {
    // Every fifth ray from outside the scene, most of those aimed away from it.
    const bool outside = i % 5 == 0;
    rays.emplace_back(test::randomPoint(rng, outside ? Vec3{2, 2, 2} : Vec3{0, 0, 0},
                                        outside ? Vec3{3, 3, 3} : Vec3{1, 1, 1}),
                      test::randomDirection(rng));
    tMax.push_back(i % 3 == 0 ? length(rng) : std::numeric_limits<float>::infinity());
  }
  const HitFilter oddFaces{nullptr,
                           [](const void*, const Ray&, std::uint32_t face, float) { return face % 2 == 1; }};
  for (std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(Bvh::kRaysInFlight),
                            std::size_t(7), rays.size()}) {
    SCOPED_TRACE(count);
    for (bool filtered : {false, true}) {
      std::vector<Hit> hits(count, Hit{1.0f, 7, 0.5f, 0.5f});
      const std::span<const Ray> some(rays.data(), count);
      const std::span<const float> ends(tMax.data(), count);
      const std::size_t hitCount = filtered ? bvh.intersect(some, 0.0f, ends, oddFaces, std::span(hits))
                                            : bvh.intersect(some, 0.0f, ends, std::span(hits));
      std::size_t expected = 0;
      for (std::size_t i = 0; i < count; ++i) {
        Hit single;
        const bool found = filtered ? bvh.intersect(rays[i], 0.0f, tMax[i], oddFaces, single)
                                    : bvh.intersect(rays[i], 0.0f, tMax[i], single);
        expected += found ? 1 : 0;
        EXPECT_TRUE(test::sameBits(hits[i], found ? single : Hit{})) << "ray " << i;
      }
      EXPECT_EQ(hitCount, expected);
      if (count == rays.size()) {
        EXPECT_GT(expected, count / 4);
      }

      // The any-hit query of the same span: blocked where the single ray is occluded.
      std::vector<std::uint8_t> blocked(count, 7);
      const std::size_t blockedCount = filtered ? bvh.occluded(some, 0.0f, ends, oddFaces, std::span(blocked))
                                                : bvh.occluded(some, 0.0f, ends, std::span(blocked));
      std::size_t expectedBlocked = 0;
      for (std::size_t i = 0; i < count; ++i) {
        const bool single =
            filtered ? bvh.occluded(rays[i], 0.0f, tMax[i], oddFaces) : bvh.occluded(rays[i], 0.0f, tMax[i]);
        expectedBlocked += single ? 1 : 0;
        EXPECT_EQ(blocked[i], single ? 1 : 0) << "ray " << i;
      }
      EXPECT_EQ(blockedCount, expectedBlocked);
      if (count == rays.size()) {
        EXPECT_GT(expectedBlocked, count / 4);
      }
    }
  }
}

}  // namespace
}  // namespace lancer
