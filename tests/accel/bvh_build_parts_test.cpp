// The pieces of the BVH build checked on their own: the Morton clusters (every reference once, in
// Morton order, equal codes in face order, none over the size) and the binned split whose sides'
// boxes come from the bins (equal, to the bit, to the boxes of the references the partition puts
// on each side).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "lancer/accel/bvh/binning.hpp"
#include "lancer/accel/bvh/build_parts.hpp"
#include "lancer/accel/bvh/morton.hpp"
#include "lancer/util/isa.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

using namespace bvh;

std::vector<PrimRef> referencesOf(const test::Soup& soup) {
  return gatherFaces(soup.positions, soup.faces, 2).refs;
}

// A soup with many faces sharing a centroid (a stack of copies), so Morton codes tie.
test::Soup soupWithTies() {
  std::mt19937 rng(11);
  test::Soup soup = test::randomSoup(rng, 3000);
  for (int copy = 0; copy < 700; ++copy) soup.triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  return soup;
}

TEST(BvhBuildParts, MortonClustersCoverEveryReferenceInOrder) {
  const test::Soup soup = soupWithTies();
  for (std::uint32_t most : {1u, 7u, 64u, kMaxClusterReferences}) {
    SCOPED_TRACE(most);
    std::vector<PrimRef> refs = referencesOf(soup);
    const std::size_t count = refs.size();
    const std::vector<Cluster> clusters = mortonClusters(refs, most, 2);
    ASSERT_EQ(refs.size(), count);
    std::uint32_t next = 0;
    for (const Cluster& cluster : clusters) {
      EXPECT_EQ(cluster.begin, next);
      EXPECT_GT(cluster.end, cluster.begin);
      EXPECT_LE(cluster.end - cluster.begin, most);
      next = cluster.end;
    }
    EXPECT_EQ(next, count);
    std::vector<std::uint32_t> faces;
    for (const PrimRef& r : refs) faces.push_back(r.face);
    // The copies share one code: the stable sort keeps them in face order.
    std::vector<std::uint32_t> copies;
    for (std::uint32_t f : faces)
      if (f >= 3000) copies.push_back(f);
    EXPECT_TRUE(std::is_sorted(copies.begin(), copies.end()));
    std::sort(faces.begin(), faces.end());
    EXPECT_TRUE(std::adjacent_find(faces.begin(), faces.end()) == faces.end()) << "a face twice";
    // The same order on one thread as on two.
    std::vector<PrimRef> serial = referencesOf(soup);
    const std::vector<Cluster> serialClusters = mortonClusters(serial, most, 1);
    ASSERT_EQ(serialClusters.size(), clusters.size());
    for (std::size_t i = 0; i < refs.size(); ++i) ASSERT_EQ(serial[i].face, refs[i].face);
  }
}

// The build's one-pass gather (keys sorted, references made once in their order) gives the references,
// slivers and clusters of gatherFaces then mortonClusters, to the bit, on faces with slivers (left
// out of the keys, so face and reference numbers differ), ties and quads.
TEST(BvhBuildParts, MortonGatherEqualsGatherThenSort) {
  std::mt19937 rng(13);
  test::Soup soup = test::adversarialSoup(rng);
  const test::Soup ties = soupWithTies();
  for (const MeshFace& face : ties.faces)
    soup.triangle(ties.positions[face.vertex[0]], ties.positions[face.vertex[1]],
                  ties.positions[face.vertex[2]]);
  soup.quad(soup.vertex({0, 0, 3}), soup.vertex({1, 0, 3}), soup.vertex({1, 1, 3}), soup.vertex({0, 1, 3}));
  for (std::uint32_t most : {1u, 7u, kMaxClusterReferences}) {
    SCOPED_TRACE(most);
    GatheredFaces gathered = gatherFaces(soup.positions, soup.faces, 2);
    ASSERT_FALSE(gathered.slivers.empty());
    const std::vector<Cluster> clusters = mortonClusters(gathered.refs, most, 2);
    for (int threads : {1, 2}) {
      const MortonFaces once = gatherMortonFaces(soup.positions, soup.faces, most, threads);
      ASSERT_EQ(once.refs.size(), gathered.refs.size());
      EXPECT_EQ(0, std::memcmp(once.refs.data(), gathered.refs.data(), once.refs.size() * sizeof(PrimRef)));
      ASSERT_EQ(once.slivers.size(), gathered.slivers.size());
      EXPECT_EQ(0, std::memcmp(once.slivers.data(), gathered.slivers.data(),
                               once.slivers.size() * sizeof(PackedTriangle)));
      ASSERT_EQ(once.clusters.size(), clusters.size());
      for (std::size_t c = 0; c < clusters.size(); ++c) {
        EXPECT_EQ(once.clusters[c].begin, clusters[c].begin);
        EXPECT_EQ(once.clusters[c].end, clusters[c].end);
      }
    }
  }
}

TEST(BvhBuildParts, SidesFromTheBinsEqualThePartitionsBoxes) {
  std::mt19937 rng(5);
  const test::Soup soup = test::randomSoup(rng, 2000);
  std::vector<PrimRef> refs = referencesOf(soup);
  const BvhBuildOptions options;
  int binned = 0;
  // Ranges of every size from 2 (fewest bins) past 32 (the most).
  for (std::uint32_t size : {2u, 3u, 5u, 9u, 17u, 31u, 33u, 100u, 2000u}) {
    for (std::uint32_t begin = 0; begin + size <= refs.size(); begin += 97 * size) {
      Range range = rangeOf(refs.data(), begin, begin + size);
      range.split = chooseSplit(refs.data(), range, options, LeafRule::SingleReference);
      if (range.split.kind != SplitKind::Binned) continue;
      ++binned;
      Range left, right;
      partition(refs.data(), range, left, right);
      ASSERT_GT(left.count(), 0u);
      ASSERT_GT(right.count(), 0u);
      const Range leftRefs = rangeOf(refs.data(), left.begin, left.end);
      const Range rightRefs = rangeOf(refs.data(), right.begin, right.end);
      for (const auto& [side, refsSide] : {std::pair{left, leftRefs}, std::pair{right, rightRefs}}) {
        for (int a = 0; a < 3; ++a) {
          EXPECT_EQ(side.bounds.lo[a], refsSide.bounds.lo[a]);
          EXPECT_EQ(side.bounds.hi[a], refsSide.bounds.hi[a]);
          EXPECT_EQ(side.centroids.lo[a], refsSide.centroids.lo[a]);
          EXPECT_EQ(side.centroids.hi[a], refsSide.centroids.hi[a]);
        }
        EXPECT_EQ(side.triangles, refsSide.triangles);
      }
      EXPECT_EQ(right.firstTriangle, range.firstTriangle + left.triangles);
    }
  }
  EXPECT_GT(binned, 20);
}

// The binning's two copies (util/isa.hpp) fill the same bins, to the bit: references of an odd count
// (the AVX2 copy takes two at a time), centroids outside the grid on both sides (clamped), negative
// and zero coordinates, quads.
TEST(BvhBuildParts, BinningCopiesFillTheSameBins) {
  if (!isa::kHaveX86_64_V3 || !isa::useX86_64_V3()) GTEST_SKIP() << "no x86-64-v3 copy on this CPU";
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f), size(0.0f, 0.5f);
  std::vector<PrimRef> refs(1001);
  for (std::size_t i = 0; i < refs.size(); ++i) {
    PrimRef& r = refs[i];
    for (int a = 0; a < 3; ++a) {
      r.lo[a] = i % 97 == 0 ? 0.0f : coordinate(rng);
      r.hi[a] = r.lo[a] + size(rng);
    }
    r.face = static_cast<std::uint32_t>(i);
    r.triangles = i % 3 == 0 ? 2 : 1;
  }
  BinGrid grid{};
  for (int a = 0; a < 3; ++a) {
    grid.origin[a] = -4.0f + float(a);  // doubled centroids run from -6 to 7: some fall off each end
    grid.scale[a] = 31.0f * (1.0f - 1e-5f) / (6.0f + float(a));
  }
  grid.last = 31.0f;
  for (std::size_t end : {std::size_t{1000}, std::size_t{1001}}) {
    std::vector<float> boxes[2];
    std::vector<std::uint32_t> counts[2];
    for (int copy = 0; copy < 2; ++copy) {
      boxes[copy].resize(3 * kMaxBins * 8);
      for (std::size_t k = 0; k < boxes[copy].size(); ++k) {
        boxes[copy][k] =
            k % 8 < 4 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
      }
      counts[copy].assign(kMaxBins * 4, 0);
    }
    fillBins<isa::Baseline>(refs.data(), 1, end, grid, boxes[0].data(), counts[0].data());
    fillBins<isa::X86_64_V3>(refs.data(), 1, end, grid, boxes[1].data(), counts[1].data());
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < kMaxBins; ++b) {
        for (int k : {0, 1, 2, 4, 5, 6}) {  // lanes 3 and 7 are never read
          const std::size_t at = (std::size_t(a) * kMaxBins + b) * 8 + k;
          ASSERT_EQ(std::memcmp(&boxes[0][at], &boxes[1][at], sizeof(float)), 0) << a << " " << b << " " << k;
        }
        ASSERT_EQ(counts[0][b * 4 + a], counts[1][b * 4 + a]) << a << " " << b;
      }
    }
    EXPECT_GT(counts[0][0 * 4 + 0], 0u);
    EXPECT_GT(counts[0][31 * 4 + 0], 0u);
  }
}

}  // namespace
}  // namespace lancer
