// Property: on thousands of random and adversarial rays, every accelerator build (the BVH and each
// kd-tree build, with options that stress them) answers exactly as the brute-force reference: same
// hit or miss, same face, same t (to 1e-6 relative), same occlusion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <sstream>
#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/naive_accel.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/accel_test_geometry.hpp"
#include "support/instrumented.hpp"

namespace lancer {
namespace {

using test::Soup;

// A built accelerator as the test sees it: its two queries, and a kd-tree whose split planes the
// adversarial rays aim at (its own for a kd-tree, the default kd build's for the BVH).
struct Built {
  std::shared_ptr<const void> keep;
  std::shared_ptr<const KdTree> planes;
  std::function<bool(const Ray&, float, float, Hit&)> intersect;
  std::function<bool(const Ray&, float, float)> occluded;
};

template <typename Tree>
Built builtOf(std::shared_ptr<const Tree> tree, std::shared_ptr<const KdTree> planes) {
  return {tree, std::move(planes),
          [tree](const Ray& r, float a, float b, Hit& h) { return tree->intersect(r, a, b, h); },
          [tree](const Ray& r, float a, float b) { return tree->occluded(r, a, b); }};
}

struct BuildCase {
  std::string name;
  std::function<Built(const Soup&)> build;
};

std::vector<BuildCase> buildCases() {
  auto kd = [](auto make) {
    return [make](const Soup& s) {
      auto tree = std::make_shared<const KdTree>(make(s));
      return builtOf(tree, tree);
    };
  };
  auto sah = [&](KdBuildOptions o) {
    return kd([o](const Soup& s) { return KdTree::buildSah(s.positions, s.faces, o); });
  };
  auto exact = [&](KdBuildOptions o) {
    return kd([o](const Soup& s) { return KdTree::buildSahExact(s.positions, s.faces, o); });
  };
  auto median = [&](KdBuildOptions o) {
    return kd([o](const Soup& s) { return KdTree::buildMedian(s.positions, s.faces, o); });
  };
  auto bvh = [](BvhBuildOptions o) {
    return [o](const Soup& s) {
      return builtOf(std::make_shared<const Bvh>(Bvh::build(s.positions, s.faces, o)),
                     std::make_shared<const KdTree>(KdTree::buildSah(s.positions, s.faces)));
    };
  };
  BvhBuildOptions bvhSerial;
  bvhSerial.threads = 1;
  BvhBuildOptions bvhSmallClusters;  // many clusters even in test-sized meshes: a deep top over them
  bvhSmallClusters.threads = 3;
  bvhSmallClusters.maxClusterReferences = 3;
  BvhBuildOptions bvhDeep = bvhSerial;  // one triangle a leaf nearly everywhere
  bvhDeep.traversalCost = 0.05f;
  BvhBuildOptions bvhWideLeaves = bvhSerial;  // leaves of eight wherever they fit
  bvhWideLeaves.traversalCost = 50.0f;
  KdBuildOptions serial;
  serial.threads = 1;
  KdBuildOptions parallel;
  parallel.threads = 2;
  KdBuildOptions cheapTraversal = serial;  // deep trees: many more split planes to trip over
  cheapTraversal.traversalCost = 0.1f;
  KdBuildOptions shallow = serial;
  shallow.maxDepth = 4;
  KdBuildOptions tinyLeaves = parallel;
  tinyLeaves.medianLeafSize = 1;
  // The default binned build with its parallel top (kd/binned_build.cpp) reaching test-sized cells,
  // and with only big straddlers clipped (the rest keep their box cut at the plane).
  KdBuildOptions parallelTop = serial;
  parallelTop.threads = 3;
  parallelTop.parallelSplitAbove = 8;
  KdBuildOptions fastBigClipped = parallelTop;
  fastBigClipped.clipAboveFraction = 0.5f;
  KdBuildOptions fastUnclipped = serial;
  fastUnclipped.clipAboveFraction = 2.0f;
  // The exact build's binned top levels (accel/kd/binned_split.hpp, the default build's search) on test-sized
  // meshes: binning down to 8 triangles, the sweep from the root, and binning on 3 threads (sweeps forked
  // with local ids).
  KdBuildOptions binnedDeep = serial;
  binnedDeep.binnedAbove = 8;
  KdBuildOptions sweepOnly = serial;
  sweepOnly.binnedAbove = 0;
  KdBuildOptions binnedParallel = serial;
  binnedParallel.threads = 3;
  binnedParallel.binnedAbove = 40;
  // Straddlers kept with their box cut at the plane instead of clipped (all of them, or the small).
  KdBuildOptions unclipped = binnedDeep;
  unclipped.clipAboveFraction = 2.0f;
  KdBuildOptions bigClipped = binnedDeep;
  bigClipped.clipAboveFraction = 0.5f;
  return {{"bvh", bvh(bvhSerial)},
          {"bvh-small-clusters", bvh(bvhSmallClusters)},
          {"bvh-deep", bvh(bvhDeep)},
          {"bvh-wide-leaves", bvh(bvhWideLeaves)},
          {"sah", sah(serial)},
          {"sah-2-threads", sah(parallel)},
          {"sah-deep", sah(cheapTraversal)},
          {"sah-shallow", sah(shallow)},
          {"sah-parallel-top", sah(parallelTop)},
          {"sah-big-clipped", sah(fastBigClipped)},
          {"sah-unclipped", sah(fastUnclipped)},
          {"exact", exact(serial)},
          {"exact-2-threads", exact(parallel)},
          {"exact-deep", exact(cheapTraversal)},
          {"exact-binned-8", exact(binnedDeep)},
          {"exact-sweep-only", exact(sweepOnly)},
          {"exact-binned-3-threads", exact(binnedParallel)},
          {"exact-binned-unclipped", exact(unclipped)},
          {"exact-binned-big-clipped", exact(bigClipped)},
          {"median", median(serial)},
          {"median-leaf-1", median(tinyLeaves)}};
}

std::string describe(const test::TestRay& r) {
  std::ostringstream out;
  out.precision(9);
  out << "origin (" << r.ray.origin.x << ", " << r.ray.origin.y << ", " << r.ray.origin.z << ") direction ("
      << r.ray.direction.x << ", " << r.ray.direction.y << ", " << r.ray.direction.z << ") t in (" << r.tMin
      << ", " << r.tMax << ")";
  return out.str();
}

void expectSameAnswers(const Soup& soup, int rayCount, std::uint32_t seed) {
  const NaiveAccel naive(soup.positions, soup.faces);
  for (const BuildCase& build : buildCases()) {
    SCOPED_TRACE(build.name);
    const Built tree = build.build(soup);
    std::mt19937 rng(seed);
    const std::vector<test::TestRay> rays =
        test::adversarialRays(soup, *tree.planes, rng, test::propertyCount(rayCount));
    int failures = 0, hits = 0;
    for (const test::TestRay& r : rays) {
      Hit expected, actual;
      const bool expectHit = naive.intersect(r.ray, r.tMin, r.tMax, expected);
      const bool gotHit = tree.intersect(r.ray, r.tMin, r.tMax, actual);
      hits += expectHit;
      bool same = expectHit == gotHit;
      if (same && expectHit) {
        same =
            expected.face == actual.face && std::abs(expected.t - actual.t) <= 1e-6f * std::abs(expected.t);
      }
      const bool expectOccluded = naive.occluded(r.ray, r.tMin, r.tMax);
      const bool gotOccluded = tree.occluded(r.ray, r.tMin, r.tMax);
      if ((!same || expectOccluded != gotOccluded) && ++failures <= 5) {
        ADD_FAILURE() << describe(r)
                      << "\n  naive: " << (expectHit ? "face " + std::to_string(expected.face) : "miss")
                      << " t " << expected.t << " occluded " << expectOccluded
                      << "\n  accel: " << (gotHit ? "face " + std::to_string(actual.face) : "miss") << " t "
                      << actual.t << " occluded " << gotOccluded;
      }
    }
    EXPECT_EQ(failures, 0) << "of " << rays.size() << " rays";
    EXPECT_GT(hits, static_cast<int>(rays.size()) / 10) << "the rays should mostly hit something";
  }
}

TEST(KdTreeProperty, RandomSoupMatchesBruteForce) {
  std::mt19937 rng(1);
  expectSameAnswers(test::randomSoup(rng, 1500), 4000, 11);
}

TEST(KdTreeProperty, GridBoxWithVerticesOnSplitPlanesMatchesBruteForce) {
  expectSameAnswers(test::gridBox(12), 8000, 12);
}

TEST(KdTreeProperty, TessellatedSphereMatchesBruteForce) {
  expectSameAnswers(test::sphere(40, 60), 6000, 13);
}

TEST(KdTreeProperty, DegenerateAndCoplanarFacesMatchBruteForce) {
  expectSameAnswers(test::adversarialSoupInGrid(), 8000, 14);
}

// What binning finds hardest: hundreds of triangles in one axis-aligned plane (many of them in the
// cell faces the tree isolates), exact duplicates, flat and zero-area boxes, a thousand tiny
// triangles in one spot inside big ones, and planes of triangles sharing one coordinate.
TEST(KdTreeProperty, CrowdedCoplanarAndDuplicatedFacesMatchBruteForce) {
  std::mt19937 rng(7);
  Soup soup;
  for (int i = 0; i < 400; ++i) {
    const int axis = i % 3;
    Vec3 a = test::randomPoint(rng, {0, 0, 0}, {1, 1, 1}), b = test::randomPoint(rng, {0, 0, 0}, {1, 1, 1}),
         c = test::randomPoint(rng, {0, 0, 0}, {1, 1, 1});
    a[axis] = b[axis] = c[axis] = i % 4 == 0 ? 0.0f : (i % 4 == 1 ? 1.0f : 0.5f);
    soup.triangle(a, b, c);
  }
  const Vec3 p{0.3f, 0.3f, 0.3f}, q{0.31f, 0.3f, 0.3f}, r{0.3f, 0.31f, 0.3f};
  for (int i = 0; i < 200; ++i) soup.triangle(p, q, r);  // one triangle 200 times
  for (int i = 0; i < 1000; ++i) {
    const Vec3 c = test::randomPoint(rng, {0.6f, 0.6f, 0.6f}, {0.6001f, 0.6001f, 0.6001f});
    soup.triangle(c, c + test::randomDirection(rng) * 1e-4f, c + test::randomDirection(rng) * 1e-4f);
  }
  for (int i = 0; i < 20; ++i) {  // big triangles through the crowd
    soup.triangle(test::randomPoint(rng, {0, 0, 0}, {1, 1, 1}), test::randomPoint(rng, {0, 0, 0}, {1, 1, 1}),
                  {0.6f, 0.6f, 0.6f});
  }
  for (int i = 0; i < 100; ++i) {  // axis-aligned right triangles on a lattice: boxes share bounds
    const float x = float(i % 10) * 0.1f, y = float(i / 10) * 0.1f;
    soup.triangle({x, y, 0.25f}, {x + 0.1f, y, 0.25f}, {x, y + 0.1f, 0.25f});
    soup.triangle({x, 0.75f, y}, {x + 0.1f, 0.75f, y}, {x, 0.75f, y + 0.1f});
  }
  expectSameAnswers(soup, 8000, 17);
}

TEST(KdTreeProperty, SingleTriangleMatchesBruteForce) {
  Soup soup;
  soup.triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0.5f});
  expectSameAnswers(soup, 1000, 18);
}

// gmsh-made fixtures (tests/data/accel, from scripts/make_accel_fixtures.sh) through the real reader.
Soup loadFixture(const std::string& name) {
  const Mesh mesh = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/accel/" + name);
  return Soup{mesh.positions, mesh.faces};
}

TEST(KdTreeProperty, GmshHoledBlockMatchesBruteForce) {
  const Soup soup = loadFixture("holed_block.msh");
  ASSERT_GT(soup.faces.size(), 1000u);
  expectSameAnswers(soup, 5000, 15);
}

TEST(KdTreeProperty, GmshQuadBoxMatchesBruteForce) {
  const Soup soup = loadFixture("quad_box.msh");
  ASSERT_TRUE(
      std::any_of(soup.faces.begin(), soup.faces.end(), [](const MeshFace& f) { return f.isQuad(); }));
  expectSameAnswers(soup, 5000, 16);
}

// A gmsh tutorial model as its authors wrote it (t5: a cube with spherical holes; curved faces
// meeting at many angles), meshed by scripts/make_accel_fixtures.sh.
TEST(KdTreeProperty, GmshTutorialT5MatchesBruteForce) {
  const Soup soup = loadFixture("gmsh_tutorial_t5.msh");
  ASSERT_GT(soup.faces.size(), 2000u);
  expectSameAnswers(soup, 4000, 19);
}

TEST(KdTreeProperty, AcceleratorDispatchMatchesBruteForce) {
  const Soup soup = test::sphere(12, 16);
  const NaiveAccel naive(soup.positions, soup.faces);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeSahExact,
                         AccelKind::KdTreeMedian, AccelKind::Naive}) {
    const Accelerator accel = Accelerator::build(soup.positions, soup.faces, kind);
    std::mt19937 rng(5);
    for (int i = 0; i < 2000; ++i) {
      const Ray ray(test::randomPoint(rng, {-1, -1, -1}, {2, 2, 2}), test::randomDirection(rng));
      Hit expected, actual;
      ASSERT_EQ(naive.intersect(ray, 0.0f, 1e30f, expected), accel.intersect(ray, 0.0f, 1e30f, actual));
      EXPECT_EQ(expected.face, actual.face);
      EXPECT_EQ(expected.t, actual.t);
      EXPECT_EQ(naive.occluded(ray, 0.0f, 1.0f), accel.occluded(ray, 0.0f, 1.0f));
    }
  }
}

}  // namespace
}  // namespace lancer
