// The pieces of the default (binned) kd-tree build checked on their own: the vector one-plane clip
// against the scalar one (the same bounds, to the bit), the exact split of small cells against a
// plain reading of the event sweep, and the whole tree, word for word, on any thread count and
// parallel-top threshold with subtrees big enough to be forked.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "lancer/accel/kd/binned_split.hpp"
#include "lancer/accel/kd/clip.hpp"
#include "lancer/accel/kd_tree.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

// Triangles that straddle planes in every way the clip meets: corners on the plane, edges along
// an axis, coordinates of both signs and zero, tiny and huge.
std::vector<std::array<Vec3, 3>> clipCases(std::mt19937& rng) {
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

float lane(__m128 v, int k) {
  alignas(16) float f[4];
  _mm_store_ps(f, v);
  return f[k];
}

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

}  // namespace
}  // namespace lancer
