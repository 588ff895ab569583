// Unit tests of the kd-tree and the Accelerator: hand-checked hits, layout invariants, stats,
// and the names the CLI accepts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <stdexcept>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

using test::Soup;

TEST(KdTree, EmptyMeshHasNoHits) {
  const KdTree tree = KdTree::buildSah({}, {});
  Hit hit;
  EXPECT_FALSE(tree.intersect(Ray({0, 0, 0}, {1, 0, 0}), 0.0f, 1e30f, hit));
  EXPECT_FALSE(tree.occluded(Ray({0, 0, 0}, {1, 0, 0}), 0.0f, 1e30f));
  EXPECT_EQ(tree.stats().triangles, 0u);
}

TEST(KdTree, SingleTriangleHitAndOpenInterval) {
  Soup soup;
  soup.triangle({0, 0, 2}, {1, 0, 2}, {0, 1, 2});
  for (const KdTree& tree :
       {KdTree::buildSah(soup.positions, soup.faces), KdTree::buildSahExact(soup.positions, soup.faces),
        KdTree::buildMedian(soup.positions, soup.faces)}) {
    Hit hit;
    const Ray ray({0.25f, 0.25f, 0}, {0, 0, 1});
    ASSERT_TRUE(tree.intersect(ray, 0.0f, 10.0f, hit));
    EXPECT_EQ(hit.face, 0u);
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
    EXPECT_FALSE(tree.intersect(ray, 0.0f, 2.0f, hit)) << "tMax is open";
    EXPECT_FALSE(tree.intersect(ray, 2.0f, 10.0f, hit)) << "tMin is open";
    EXPECT_TRUE(tree.occluded(ray, 0.0f, 3.0f));
    EXPECT_FALSE(tree.occluded(ray, 0.0f, 1.5f));
    EXPECT_FALSE(tree.intersect(Ray({2, 2, 0}, {0, 0, 1}), 0.0f, 10.0f, hit));
  }
}

TEST(KdTree, QuadIsOneFaceAndDuplicateTiesGoToLowerFace) {
  Soup soup;
  const auto a = soup.vertex({0, 0, 1}), b = soup.vertex({1, 0, 1}), c = soup.vertex({1, 1, 1}),
             d = soup.vertex({0, 1, 1});
  soup.triangle({5, 5, 5}, {6, 5, 5}, {5, 6, 5});
  soup.quad(a, b, c, d);  // face 1
  soup.quad(a, b, c, d);  // face 2, same place
  const KdTree tree = KdTree::buildSah(soup.positions, soup.faces);
  EXPECT_EQ(tree.stats().faces, 3u);
  EXPECT_EQ(tree.stats().triangles, 5u);
  Hit hit;
  ASSERT_TRUE(tree.intersect(Ray({0.75f, 0.25f, 0}, {0, 0, 1}), 0.0f, 10.0f, hit));
  EXPECT_EQ(hit.face, 1u);
  ASSERT_TRUE(tree.intersect(Ray({0.5f, 0.5f, 0}, {0, 0, 1}), 0.0f, 10.0f, hit)) << "on the quad's diagonal";
  EXPECT_EQ(hit.face, 1u);
}

TEST(KdTree, RayInsideSplitPlaneSeesFacesOnBothSides) {
  // Two walls touching the plane x = 1 from either side, and a ray running inside that plane.
  Soup soup = test::gridBox(2);
  const KdTree tree = KdTree::buildSah(soup.positions, soup.faces);
  Hit hit;
  ASSERT_TRUE(tree.intersect(Ray({1, 1, -5}, {0, 0, 1}), 0.0f, 1e30f, hit));
  EXPECT_FLOAT_EQ(hit.t, 5.0f);
}

TEST(KdTree, LayoutInvariants) {
  std::mt19937 rng(3);
  const Soup soup = test::randomSoup(rng, 2000);
  for (const KdTree& tree :
       {KdTree::buildSah(soup.positions, soup.faces), KdTree::buildSahExact(soup.positions, soup.faces),
        KdTree::buildMedian(soup.positions, soup.faces)}) {
    const auto nodes = tree.layout();
    std::set<std::uint32_t> seen;
    std::uint64_t leaves = 0, inner = 0;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
      const KdNode node = nodes[stack.back()];
      stack.pop_back();
      if (node.isLeaf()) {
        ++leaves;
        for (std::uint32_t offset : tree.leafTriangles(node)) {
          ASSERT_LE(offset + KdTree::kTriangleWords, nodes.size());
          ASSERT_LT(tree.triangleAt(offset).face, soup.faces.size());
          seen.insert(offset);
        }
      } else {
        ++inner;
        EXPECT_EQ(node.firstChild() % 2, 0u) << "sibling pairs start at even indices";
        ASSERT_LT(node.firstChild() + 1, nodes.size());
        stack.push_back(node.firstChild());
        stack.push_back(node.firstChild() + 1);
      }
    }
    EXPECT_EQ(inner + leaves, tree.stats().nodes);
    EXPECT_EQ(leaves, tree.stats().leaves);
    EXPECT_EQ(seen.size() + tree.slivers().size(), tree.stats().triangles)
        << "every triangle is in some leaf";
    std::set<std::uint32_t> faces;
    for (std::uint32_t offset : seen) faces.insert(tree.triangleAt(offset).face);
    for (const PackedTriangle& t : tree.slivers()) faces.insert(t.face);
    EXPECT_EQ(faces.size(), soup.faces.size()) << "every face is in the tree";
    EXPECT_LE(tree.stats().depth, static_cast<std::uint64_t>(KdTree::kMaxDepth));
  }
}

TEST(KdTree, StatsDescribeTheTree) {
  const Soup soup = test::sphere(60, 80);
  const KdTree tree = KdTree::buildSah(soup.positions, soup.faces);
  const AccelStats& s = tree.stats();
  EXPECT_EQ(s.kind, "kdtree-sah");
  EXPECT_EQ(s.faces, soup.faces.size());
  EXPECT_EQ(s.nodes, 2 * (s.leaves - 1) + 1) << "a full binary tree";
  EXPECT_GT(s.depth, 5u);
  EXPECT_GT(s.meanTrianglesPerLeaf, 0.9);
  EXPECT_GT(s.sahCost, 0.0);
  EXPECT_EQ(s.bytes, tree.layout().size() * sizeof(KdNode) + tree.slivers().size() * sizeof(PackedTriangle));
  EXPECT_LE(s.bytesPerTriangle(), 80.0) << "the bench meshes take under 64; a UV sphere is less kind";
  EXPECT_GE(s.buildSeconds, 0.0);
  // The SAH tree beats the median tree on its own cost model.
  const KdTree median = KdTree::buildMedian(soup.positions, soup.faces);
  EXPECT_LT(s.sahCost, median.stats().sahCost);
}

TEST(KdTree, AxisAlignedFacesGetFlatCells) {
  // A box of planar faces (a CAD part in miniature): the SAH build isolates each face in a flat
  // cell, so its expected ray cost is far below the median tree's, whose cells straddle the faces.
  const Soup soup = test::gridBox(16);
  const KdTree sah = KdTree::buildSah(soup.positions, soup.faces);
  const KdTree median = KdTree::buildMedian(soup.positions, soup.faces);
  EXPECT_LT(sah.stats().sahCost, 0.5 * median.stats().sahCost);
}

TEST(KdTree, BinnedBuildMatchesTheExactBuildsCost) {
  // The default binned build against the exact sweep on the same cost model: within a few percent
  // on small test meshes (on the 1M bench bracket within 1%).
  std::mt19937 rng(3);
  for (const Soup& soup : {test::sphere(60, 80), test::gridBox(16), test::randomSoup(rng, 3000)}) {
    const KdTree binned = KdTree::buildSah(soup.positions, soup.faces);
    const KdTree exact = KdTree::buildSahExact(soup.positions, soup.faces);
    EXPECT_EQ(exact.stats().kind, "kdtree-sah-exact");
    EXPECT_LT(binned.stats().sahCost, 1.06 * exact.stats().sahCost) << soup.faces.size() << " faces";
  }
}

TEST(Accelerator, ParsesTheNamesTheCliAccepts) {
  EXPECT_EQ(parseAccelKind("bvh"), AccelKind::Bvh);
  EXPECT_EQ(kDefaultAccel, AccelKind::Bvh);
  EXPECT_EQ(kDefaultAccelName, "bvh");
  EXPECT_EQ(parseAccelKind("kdtree-sah"), AccelKind::KdTreeSah);
  EXPECT_EQ(parseAccelKind("kdtree-sah-exact"), AccelKind::KdTreeSahExact);
  EXPECT_EQ(parseAccelKind("kdtree-median"), AccelKind::KdTreeMedian);
  EXPECT_EQ(parseAccelKind("naive"), AccelKind::Naive);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeSahExact,
                         AccelKind::KdTreeMedian, AccelKind::Naive}) {
    EXPECT_EQ(parseAccelKind(accelKindName(kind)), kind);
  }
  try {
    parseAccelKind("octree");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "unknown accelerator 'octree': expected bvh, kdtree-sah, kdtree-sah-exact, "
                 "kdtree-median or naive");
  }
}

TEST(Accelerator, StatsForEveryKind) {
  const Soup soup = test::sphere(10, 12);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeSahExact,
                         AccelKind::KdTreeMedian, AccelKind::Naive}) {
    const Accelerator accel = Accelerator::build(soup.positions, soup.faces, kind);
    EXPECT_EQ(accel.stats().kind, accelKindName(kind));
    EXPECT_EQ(accel.stats().faces, soup.faces.size());
    EXPECT_GT(accel.stats().bytes, 0u);
    Hit hit;
    EXPECT_TRUE(accel.intersect(Ray({0.5f, 0.5f, -1}, {0, 0, 1}), 0.0f, 1e30f, hit));
  }
}

}  // namespace
}  // namespace lancer
