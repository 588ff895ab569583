// The pieces of the default (binned) kd-tree build checked on their own: the vector one-plane clip
// against the scalar one (the same bounds, to the bit), the exact split of small cells against a
// plain reading of the event sweep, the whole tree, word for word, on any thread count and
// parallel-top threshold with subtrees big enough to be forked; the arenas' leaf ids, the
// layout's triangles written from the mesh again (quads, slivers, several gather chunks), and a
// tree big enough that the build hands finished references' pages back while it runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/build.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

// Triangles that straddle planes in every way the clip meets: corners on the plane, edges along
// an axis, coordinates of both signs and zero, tiny and huge.
[[maybe_unused]] std::vector<std::array<Vec3, 3>> clipCases(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_int_distribution<int> grid(-2, 2);
  std::vector<std::array<Vec3, 3>> cases;
  for (int i = 0; i < 4000; ++i) {
    const float scale = i % 3 == 0 ? 1e-3f : (i % 3 == 1 ? 1.0f : 1e4f);
    std::array<Vec3, 3> t;
    for (Vec3& c : t) {
      if (i % 4 == 0)
        c = {float(grid(rng)), float(grid(rng)), float(grid(rng))};  // on the planes x = 0 etc.
      else
        c = {u(rng) * scale, u(rng) * scale, u(rng) * scale};
    }
    if (i % 5 == 0) t[1].y = t[0].y;  // an edge along an axis
    cases.push_back(t);
  }
  return cases;
}

#if defined(__AVX2__)
float lane(__m128 v, int k) {
  alignas(16) float f[4];
  _mm_store_ps(f, v);
  return f[k];
}
#endif

TEST(KdBuildParts, VectorClipGivesTheScalarBoundsToTheBit) {
#if defined(__AVX2__)
  std::mt19937 rng(11);
  int compared = 0;
  for (const std::array<Vec3, 3>& t : clipCases(rng)) {
    const PackedTriangle packed{t[0], t[1], t[2], 0};
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = std::min({t[0][axis], t[1][axis], t[2][axis]});
      const float hi = std::max({t[0][axis], t[1][axis], t[2][axis]});
      for (const float plane : {0.0f, 0.5f * (lo + hi), lo + 0.25f * (hi - lo)}) {
        if (!(plane > lo && plane < hi)) continue;  // the build clips straddlers only
        Aabb below, above;
        splitTriangleBounds(t, axis, plane, below, above);
        __m128 lower[2], upper[2];
        splitTriangleBounds(packed, axis, plane, lower, upper);
        const Aabb* scalar[2] = {&below, &above};
        for (int side = 0; side < 2; ++side) {
          for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(std::bit_cast<std::uint32_t>(lane(lower[side], k)),
                      std::bit_cast<std::uint32_t>(scalar[side]->lower[k]))
                << "side " << side << " axis " << k;
            EXPECT_EQ(std::bit_cast<std::uint32_t>(lane(upper[side], k)),
                      std::bit_cast<std::uint32_t>(scalar[side]->upper[k]))
                << "side " << side << " axis " << k;
          }
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 5000);
#else
  GTEST_SKIP() << "no AVX2: the build uses the scalar clip only";
#endif
}

// The exact sweep's choice for a few references, read plainly: every bound strictly inside the
// cell, nl = #(lo < p), nr = #(hi > p), planars on either side, the empty-space bonus for a slab
// of emptySpaceMinFraction, flat cells at the faces.
float referenceSmallCost(const std::vector<binned::Ref>& refs, const binned::Box& cell,
                         const KdBuildOptions& o) {
  const float area = cell.area();
  float best = std::numeric_limits<float>::infinity();
  const auto n = static_cast<std::uint32_t>(refs.size());
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = cell.lo[axis], hi = cell.hi[axis];
    if (!(hi > lo)) continue;
    const float a = cell.hi[(axis + 1) % 3] - cell.lo[(axis + 1) % 3];
    const float b = cell.hi[(axis + 2) % 3] - cell.lo[(axis + 2) % 3];
    auto side = [&](float length) { return 2.0f * (a * b + length * (a + b)) / area; };
    std::uint32_t atLo = 0, atHi = 0;
    for (const binned::Ref& r : refs) {
      atLo += r.lo[axis] == r.hi[axis] && r.lo[axis] == lo;
      atHi += r.lo[axis] == r.hi[axis] && r.hi[axis] == hi;
    }
    const float flat = 2.0f * a * b / area;
    if (atLo > 0) {
      const float c = o.traversalCost + o.intersectionCost * (flat * float(atLo) + float(n - atLo));
      best = std::min(best, n > atLo ? c : c * o.emptySpaceFactor);
    }
    if (atHi > 0) {
      const float c = o.traversalCost + o.intersectionCost * (float(n - atHi) + flat * float(atHi));
      best = std::min(best, n > atHi ? c : c * o.emptySpaceFactor);
    }
    for (const binned::Ref& candidate : refs) {
      for (const float p : {candidate.lo[axis], candidate.hi[axis]}) {
        if (!(p > lo && p < hi)) continue;
        std::uint32_t nl = 0, nr = 0, np = 0;
        for (const binned::Ref& r : refs) {
          nl += r.lo[axis] < p;
          nr += r.hi[axis] > p;
          np += r.lo[axis] == p && r.hi[axis] == p;
        }
        const bool wideLeft = p - lo >= o.emptySpaceMinFraction * (hi - lo);
        const bool wideRight = hi - p >= o.emptySpaceMinFraction * (hi - lo);
        auto cost = [&](std::uint32_t cl, std::uint32_t cr) {
          const float c =
              o.traversalCost + o.intersectionCost * (side(p - lo) * float(cl) + side(hi - p) * float(cr));
          return ((cl == 0 && wideLeft) || (cr == 0 && wideRight)) ? c * o.emptySpaceFactor : c;
        };
        best = std::min({best, cost(nl + np, nr), cost(nl, nr + np)});
      }
    }
  }
  return best;
}

TEST(KdBuildParts, ExactSmallSplitFindsTheSweepsCheapestPlane) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::uniform_int_distribution<int> snap(0, 4);
  const KdBuildOptions options;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::size_t n = 1 + std::size_t(trial) % (binned::kSmallCell - 1);
    binned::Box cell;
    for (int k = 0; k < 3; ++k) {
      cell.lo[k] = 0.0f;
      cell.hi[k] = 1.0f + float(k);
    }
    std::vector<binned::Ref> refs(n);
    for (binned::Ref& r : refs) {
      for (int k = 0; k < 3; ++k) {
        // Bounds often on a few shared positions (faces of the cell, flat references): the ties
        // and planars the sweep has rules for.
        float a = trial % 2 ? float(snap(rng)) / 4.0f * cell.hi[k] : u(rng) * cell.hi[k];
        float b = trial % 3 ? a + u(rng) * (cell.hi[k] - a) : a;
        r.lo[k] = std::min(a, b);
        r.hi[k] = std::max(a, b);
      }
      r.id = 0;
      r.unused = 0;
    }
    const binned::Split split = binned::exactSmallSplit(refs.data(), n, cell, options);
    const float reference = referenceSmallCost(refs, cell, options);
    if (std::isinf(reference)) {
      EXPECT_LT(split.axis, 0) << "trial " << trial;
      continue;
    }
    ASSERT_GE(split.axis, 0) << "trial " << trial;
    EXPECT_NEAR(split.cost, reference, 1e-5f * reference) << "trial " << trial << ", " << n << " references";
  }
}

TEST(KdBuildParts, TreeIsTheSameWordForWordForAnyThreadCountWithForkedSubtrees) {
  // Enough triangles that subtrees of 4096+ references are forked to idle threads, and cells big
  // enough for the parallel top when its threshold is lowered.
  std::mt19937 rng(9);
  const test::Soup soup = test::randomSoup(rng, 30000);
  KdBuildOptions one;
  one.threads = 1;
  const KdTree reference = KdTree::buildSah(soup.positions, soup.faces, one);
  for (const int threads : {2, 3, 4}) {
    for (const std::uint32_t top : {1u << 22, 5000u}) {
      SCOPED_TRACE(testing::Message() << threads << " threads, parallel top above " << top);
      KdBuildOptions o;
      o.threads = threads;
      o.parallelSplitAbove = top;
      const KdTree tree = KdTree::buildSah(soup.positions, soup.faces, o);
      ASSERT_EQ(tree.layout().size(), reference.layout().size());
      EXPECT_TRUE(std::equal(
          tree.layout().begin(), tree.layout().end(), reference.layout().begin(),
          [](const KdNode& a, const KdNode& b) { return a.payload == b.payload && a.bits == b.bits; }));
      EXPECT_EQ(tree.stats().sahCost, reference.stats().sahCost);
    }
  }
}

TEST(KdBuildParts, ArenaKeepsEveryLeafsIdsAcrossItsBlocks) {
  // Leaves of 0 to 70000 ids: blocks start small and double, and a leaf bigger than the largest
  // block gets a block of its own; no leaf's ids move or mix with another's.
  BuildArena arena;
  std::vector<std::pair<BuildNode*, std::vector<std::uint32_t>>> leaves;
  std::mt19937 rng(4);
  std::uniform_int_distribution<std::uint32_t> id(0, 1u << 30);
  for (const std::size_t size : {0, 1, 3, 1000, 1021, 5, 70000, 2, 0, 65536, 40000, 7, 33000}) {
    std::vector<std::uint32_t> ids(size);
    for (std::uint32_t& i : ids) i = id(rng);
    leaves.emplace_back(arena.leaf(ids), ids);
  }
  for (const auto& [node, ids] : leaves) {
    EXPECT_LT(node->axis, 0);
    const std::span<const std::uint32_t> kept = node->leafIds();
    ASSERT_EQ(kept.size(), ids.size());
    EXPECT_TRUE(std::equal(kept.begin(), kept.end(), ids.begin())) << ids.size() << " ids";
  }
}

// Calls visit(triangle) for each triangle of each leaf of the tree (a triangle in several leaves
// once for each).
template <typename Visit>
void forEachLeafTriangle(const KdTree& tree, Visit&& visit) {
  const auto nodes = tree.layout();
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const KdNode node = nodes[stack.back()];
    stack.pop_back();
    if (!node.isLeaf()) {
      stack.push_back(node.firstChild());
      stack.push_back(node.firstChild() + 1);
      continue;
    }
    for (const std::uint32_t offset : tree.leafTriangles(node)) visit(tree.triangleAt(offset));
  }
}

// A mesh of every kind of face the gather meets, in several chunks of its plan: triangles, quads,
// quads with one sliver half, and slivers.
test::Soup mixedFaces(std::mt19937& rng, int faces) {
  test::Soup soup;
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < faces; ++i) {
    const Vec3 c = test::randomPoint(rng, {0, 0, 0}, {1, 1, 1});
    const Vec3 a = c + Vec3{0.01f * u(rng), 0, 0}, b = c + Vec3{0, 0.01f * u(rng) + 1e-3f, 0};
    const Vec3 d = c + Vec3{0.005f, 0.005f, 0.01f * u(rng) + 1e-3f};
    switch (i % 5) {
      case 0:
      case 1:
        soup.triangle(c, a + Vec3{1e-3f, 0, 0}, b);
        break;
      case 2:
        soup.quad(soup.vertex(c), soup.vertex(a + Vec3{1e-3f, 0, 0}), soup.vertex(d), soup.vertex(b));
        break;
      case 3:  // (0,1,2) a sliver (1 on the segment 0-2), (0,2,3) not
        soup.quad(soup.vertex(c), soup.vertex(c + (d - c) * 0.5f), soup.vertex(d), soup.vertex(b));
        break;
      default:
        soup.triangle(c, c + (d - c) * 0.25f, d);
        break;  // a sliver
    }
  }
  return soup;
}

TEST(KdBuildParts, LayoutTrianglesAreTheMeshsAfterTheGatherIsFreed) {
  // The assembler frees the gathered triangles and writes the layout's from the mesh again: each
  // must be its face's triangle (the same corners, to the bit), every non-sliver half present,
  // over more than one gather chunk and on any thread count.
  std::mt19937 rng(17);
  const test::Soup soup = mixedFaces(rng, 40000);
  ASSERT_GT(gatherChunkPlan(soup.faces.size()).chunks, 1u);
  const KdBuildInput gathered = gatherTriangles(soup.positions, soup.faces);
  ASSERT_GT(gathered.slivers.size(), 10000u);
  // (face, corner 1 of the half) -> the half's packed triangle, as the gather made it.
  std::map<std::pair<std::uint32_t, float>, PackedTriangle> expected;
  for (const PackedTriangle& t : gathered.triangles) expected[{t.face, t.v1.x}] = t;
  ASSERT_EQ(expected.size(), gathered.triangles.size());
  for (const int threads : {1, 2, 3}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    KdBuildOptions options;
    options.threads = threads;
    for (const KdTree& tree : {KdTree::buildSah(soup.positions, soup.faces, options),
                               KdTree::buildMedian(soup.positions, soup.faces, options)}) {
      std::set<std::pair<std::uint32_t, float>> seen;
      forEachLeafTriangle(tree, [&](const PackedTriangle& t) {
        const auto found = expected.find({t.face, t.v1.x});
        ASSERT_NE(found, expected.end()) << "face " << t.face;
        EXPECT_EQ(std::memcmp(&found->second, &t, sizeof t), 0) << "face " << t.face;
        seen.insert(found->first);
      });
      EXPECT_EQ(seen.size(), expected.size()) << "every tree triangle is in a leaf";
      EXPECT_EQ(tree.slivers().size(), gathered.slivers.size());
    }
  }
}

TEST(KdBuildParts, BigTreeWhoseBuildGivesPagesBackMatchesBruteForce) {
  // 160K small triangles: cells of 64K+ references hand their finished left subtree's pages back
  // before the right one is built (RefBuffer::release); a live reference lost there would drop
  // triangles from the tree or put zeroed ones in it.
  std::mt19937 rng(23);
  test::Soup soup;
  std::uniform_real_distribution<float> size(0.001f, 0.01f);
  for (int i = 0; i < 160000; ++i) {
    const Vec3 c = test::randomPoint(rng, {0, 0, 0}, {1, 1, 1});
    const float s = size(rng);
    soup.triangle(c + test::randomDirection(rng) * s, c + test::randomDirection(rng) * s,
                  c + test::randomDirection(rng) * s);
  }
  const NaiveAccel naive(soup.positions, soup.faces);
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    KdBuildOptions options;
    options.threads = threads;
    const KdTree tree = KdTree::buildSah(soup.positions, soup.faces, options);
    std::set<std::uint32_t> faces;
    forEachLeafTriangle(tree, [&](const PackedTriangle& t) { faces.insert(t.face); });
    EXPECT_EQ(faces.size() + tree.slivers().size(), soup.faces.size()) << "every face is in a leaf";
    std::mt19937 rays(5);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
      const Ray ray(test::randomPoint(rays, {0, 0, 0}, {1, 1, 1}), test::randomDirection(rays));
      Hit expected, actual;
      const bool expectHit = naive.intersect(ray, 0.0f, 10.0f, expected);
      ASSERT_EQ(tree.intersect(ray, 0.0f, 10.0f, actual), expectHit) << "ray " << i;
      if (!expectHit) continue;
      ++hits;
      EXPECT_EQ(actual.face, expected.face) << "ray " << i;
      EXPECT_EQ(actual.t, expected.t) << "ray " << i;
    }
    EXPECT_GT(hits, 100);
  }
}

}  // namespace
}  // namespace lancer
