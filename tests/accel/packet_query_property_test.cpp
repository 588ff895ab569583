// Property: the BVH's and the kd-tree's packet queries answer every lane exactly as the single-ray query does
// (same hit or miss, same face, same t, same barycentrics, to the bit; same occlusion), on the
// adversarial ray sets of the kd-tree property test grouped eight at a time by direction (so that the
// packet walks the tree together) and in arrival order (mixed directions, traced one by one), on
// coherent camera and shadow packets, through the clipped queries, and on the watertight rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <random>
#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/face_clip_sets.hpp"
#include "support/accel_test_geometry.hpp"
#include "support/instrumented.hpp"

namespace lancer {
namespace {

using test::Soup;
using test::TestRay;

// The rays in packets of eight: sorted by the signs of their directions (coherent packets), or as
// they come (mixed). Every fifth packet leaves a lane out.
std::vector<std::pair<RayPacket, std::uint32_t>> packetsOf(std::vector<TestRay> rays, bool bySigns) {
  if (bySigns) {
    auto signs = [](const TestRay& r) {
      return (r.ray.invDirection.x < 0) | (r.ray.invDirection.y < 0) << 1 | (r.ray.invDirection.z < 0) << 2;
    };
    std::stable_sort(rays.begin(), rays.end(),
                     [&](const TestRay& a, const TestRay& b) { return signs(a) < signs(b); });
  }
  std::vector<std::pair<RayPacket, std::uint32_t>> packets;
  for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
    RayPacket packet;
    std::uint32_t active = 0;
    for (int i = 0; i < kPacketSize && first + i < rays.size(); ++i) {
      packet.ray[i] = rays[first + i].ray;
      packet.tMin[i] = rays[first + i].tMin;
      packet.tMax[i] = rays[first + i].tMax;
      active |= 1u << i;
    }
    if (packets.size() % 5 == 4) active &= ~(1u << (packets.size() / 5 % kPacketSize));
    packets.emplace_back(packet, active);
  }
  return packets;
}

// Traces every packet both ways and counts the lanes that differ; `hits` counts the lanes that hit.
template <typename Single, typename Packet, typename SingleOccluded, typename PacketOccluded>
int countDifferences(const std::vector<std::pair<RayPacket, std::uint32_t>>& packets, Single single,
                     Packet packetQuery, SingleOccluded singleOccluded, PacketOccluded packetOccluded,
                     int& hits) {
  int failures = 0;
  for (const auto& [packet, active] : packets) {
    Hit packetHits[kPacketSize];
    const std::uint32_t hitLanes = packetQuery(packet, active, std::span<Hit, kPacketSize>(packetHits));
    const std::uint32_t blockedLanes = packetOccluded(packet, active);
    EXPECT_EQ(hitLanes & ~active, 0u);
    EXPECT_EQ(blockedLanes & ~active, 0u);
    for (int i = 0; i < kPacketSize; ++i) {
      if ((active >> i & 1u) == 0) continue;
      Hit expected;
      const bool expectHit = single(packet.ray[i], packet.tMin[i], packet.tMax[i], expected);
      const bool gotHit = (hitLanes >> i & 1u) != 0;
      const bool expectBlocked = singleOccluded(packet.ray[i], packet.tMin[i], packet.tMax[i]);
      const bool gotBlocked = (blockedLanes >> i & 1u) != 0;
      hits += expectHit;
      const bool same = expectHit == gotHit && (!expectHit || test::sameBits(expected, packetHits[i])) &&
                        expectBlocked == gotBlocked;
      if (!same && ++failures <= 5) {
        ADD_FAILURE() << "lane " << i << ": single " << (expectHit ? std::to_string(expected.face) : "miss")
                      << " t " << expected.t << " b " << expected.b1 << "," << expected.b2 << " blocked "
                      << expectBlocked << "; packet "
                      << (gotHit ? std::to_string(packetHits[i].face) : "miss") << " t " << packetHits[i].t
                      << " b " << packetHits[i].b1 << "," << packetHits[i].b2 << " blocked " << gotBlocked;
      }
    }
  }
  return failures;
}

template <typename Tree>
int countDifferences(const Tree& tree, const std::vector<std::pair<RayPacket, std::uint32_t>>& packets,
                     int& hits) {
  return countDifferences(
      packets, [&](const Ray& r, float a, float b, Hit& h) { return tree.intersect(r, a, b, h); },
      [&](const RayPacket& p, std::uint32_t m, std::span<Hit, kPacketSize> h) {
        return tree.intersect(p, m, h);
      },
      [&](const Ray& r, float a, float b) { return tree.occluded(r, a, b); },
      [&](const RayPacket& p, std::uint32_t m) { return tree.occluded(p, m); }, hits);
}

// Pinhole views of the soup's box from several sides in 4x2-pixel packets, and from the points
// they hit, shadow packets towards a point light (t up to 1).
template <typename Tree>
std::vector<TestRay> coherentRays(const Soup& soup, const Tree& tree, std::mt19937& rng) {
  Aabb box;
  for (const Vec3& p : soup.positions) box.extend(p);
  std::vector<TestRay> rays;
  for (int view = 0; view < 6; ++view) {
    const Vec3 eye = box.center() + test::randomDirection(rng) * (length(box.extent()) * 1.5f);
    const Vec3 forward = normalize(box.center() - eye);
    const Vec3 right = normalize(cross(forward, std::abs(forward.z) < 0.9f ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
    const Vec3 up = cross(right, forward);
    const Vec3 light = box.center() + test::randomDirection(rng) * (length(box.extent()) * 2.0f);
    const int size = 32;
    for (int by = 0; by < size; by += 2) {
      for (int bx = 0; bx < size; bx += 4) {
        for (int p = 0; p < kPacketSize; ++p) {
          const float u = (float(bx + p % 4) + 0.5f) / size - 0.5f,
                      v = (float(by + p / 4) + 0.5f) / size - 0.5f;
          TestRay r;
          r.ray = Ray(eye, forward + right * u + up * v);
          rays.push_back(r);
        }
      }
    }
    // Shadow rays from each hit, in the same order (so neighbours stay neighbours).
    const std::size_t primaryEnd = rays.size();
    for (std::size_t i = primaryEnd - size * size; i < primaryEnd; ++i) {
      Hit hit;
      if (!tree.intersect(rays[i].ray, 0.0f, rays[i].tMax, hit)) continue;
      TestRay s;
      const Vec3 from = rays[i].ray.at(hit.t * 0.999f);
      s.ray = Ray(from, light - from);
      s.tMax = 1.0f;
      rays.push_back(s);
    }
  }
  return rays;
}

// One tree's packets against its single rays; `planes` is the kd-tree the adversarial rays aim at.
template <typename Tree>
void expectSameAnswersOf(const Tree& tree, const KdTree& planes, const Soup& soup, int rayCount,
                         std::uint32_t seed) {
  SCOPED_TRACE(tree.stats().kind + " depth " + std::to_string(tree.stats().depth));
  std::mt19937 rng(seed);
  const std::vector<TestRay> rays = test::adversarialRays(soup, planes, rng, test::propertyCount(rayCount));
  int hits = 0;
  EXPECT_EQ(countDifferences(tree, packetsOf(rays, true), hits), 0) << "coherent packets";
  EXPECT_EQ(countDifferences(tree, packetsOf(rays, false), hits), 0) << "mixed packets";
  EXPECT_GT(hits, static_cast<int>(rays.size()) / 5);
  hits = 0;
  EXPECT_EQ(countDifferences(tree, packetsOf(coherentRays(soup, tree, rng), false), hits), 0)
      << "camera and shadow packets";
  EXPECT_GT(hits, 400);
}

void expectSameAnswers(const Soup& soup, int rayCount, std::uint32_t seed) {
  KdBuildOptions serial;
  serial.threads = 1;
  KdBuildOptions deep = serial;
  deep.traversalCost = 0.1f;
  const KdTree trees[] = {KdTree::buildSah(soup.positions, soup.faces, serial),
                          KdTree::buildSah(soup.positions, soup.faces, deep),
                          KdTree::buildMedian(soup.positions, soup.faces, serial)};
  for (const KdTree& tree : trees) expectSameAnswersOf(tree, tree, soup, rayCount, seed);
  BvhBuildOptions bvhSerial;
  bvhSerial.threads = 1;
  BvhBuildOptions bvhDeep = bvhSerial;
  bvhDeep.traversalCost = 0.05f;
  for (const BvhBuildOptions& options : {bvhSerial, bvhDeep})
    expectSameAnswersOf(Bvh::build(soup.positions, soup.faces, options), trees[0], soup, rayCount, seed);
}

TEST(PacketQueryProperty, RandomSoup) {
  std::mt19937 rng(1);
  expectSameAnswers(test::randomSoup(rng, 1500), 4000, 11);
}

TEST(PacketQueryProperty, GridBoxWithVerticesOnSplitPlanes) {
  expectSameAnswers(test::gridBox(12), 8000, 12);
}

TEST(PacketQueryProperty, TessellatedSphere) { expectSameAnswers(test::sphere(40, 60), 6000, 13); }

TEST(PacketQueryProperty, DegenerateAndCoplanarFaces) {
  expectSameAnswers(test::adversarialSoupInGrid(), 8000, 14);
}

Soup loadFixture(const std::string& name) {
  const Mesh mesh = readMsh(std::string(LANCER_TEST_DATA_DIR) + "/" + name);
  return Soup{mesh.positions, mesh.faces};
}

TEST(PacketQueryProperty, GmshHoledBlockAndQuadBox) {
  expectSameAnswers(loadFixture("accel/holed_block.msh"), 5000, 15);
  expectSameAnswers(loadFixture("accel/quad_box.msh"), 5000, 16);
}

// A gmsh tutorial model as its authors wrote it (scripts/make_accel_fixtures.sh).
TEST(PacketQueryProperty, GmshTutorialT5) {
  expectSameAnswers(loadFixture("accel/gmsh_tutorial_t5.msh"), 4000, 17);
}

TEST(PacketQueryProperty, ClippedQueriesSeeThroughTheSameFaces) {
  // A sphere cut by two planes of its own inside a grid box: rays pass removed faces.
  Soup soup = test::sphere(24, 32, {2, 2, 2}, 1.5f);
  const auto sphereFaces = static_cast<std::uint32_t>(soup.faces.size());
  const Soup box = test::gridBox(4);
  const auto base = static_cast<std::uint32_t>(soup.positions.size());
  soup.positions.insert(soup.positions.end(), box.positions.begin(), box.positions.end());
  for (MeshFace face : box.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += base;
    soup.faces.push_back(face);
  }
  FaceClipSets clips;
  clips.planes = {{{2, 2, 2}, normalize(Vec3{1, 0.3f, 0})}, {{2, 2.5f, 2}, {0, 0, 1}}};
  clips.caps = {1, 1};
  clips.ranges.push_back({0, sphereFaces, 0, 2});
  const HitFilter filter{&clips, [](const void* c, const Ray& ray, std::uint32_t face, float t) {
                           return static_cast<const FaceClipSets*>(c)->keeps(ray, face, t);
                         }};
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeMedian, AccelKind::Naive}) {
    SCOPED_TRACE(std::string(accelKindName(kind)));
    const Accelerator accel = Accelerator::build(soup.positions, soup.faces, kind);
    const KdTree tree = KdTree::buildSah(soup.positions, soup.faces);
    std::mt19937 rng(7);
    std::vector<TestRay> rays = test::adversarialRays(soup, tree, rng, 3000);
    const std::vector<TestRay> coherent = coherentRays(soup, tree, rng);
    rays.insert(rays.end(), coherent.begin(), coherent.end());
    for (const bool bySigns : {true, false}) {
      int hits = 0;
      const int clipped = countDifferences(
          packetsOf(rays, bySigns),
          [&](const Ray& r, float a, float b, Hit& h) { return accel.intersect(r, a, b, filter, h); },
          [&](const RayPacket& p, std::uint32_t m, std::span<Hit, kPacketSize> h) {
            return accel.intersect(p, m, filter, h);
          },
          [&](const Ray& r, float a, float b) { return accel.occluded(r, a, b, filter); },
          [&](const RayPacket& p, std::uint32_t m) { return accel.occluded(p, m, filter); }, hits);
      EXPECT_EQ(clipped, 0) << "clipped, coherent " << bySigns;
      const int unclipped = countDifferences(
          packetsOf(rays, bySigns),
          [&](const Ray& r, float a, float b, Hit& h) { return accel.intersect(r, a, b, h); },
          [&](const RayPacket& p, std::uint32_t m, std::span<Hit, kPacketSize> h) {
            return accel.intersect(p, m, h);
          },
          [&](const Ray& r, float a, float b) { return accel.occluded(r, a, b); },
          [&](const RayPacket& p, std::uint32_t m) { return accel.occluded(p, m); }, hits);
      EXPECT_EQ(unclipped, 0) << "unclipped, coherent " << bySigns;
      EXPECT_GT(hits, 2000);
    }
  }
}

// The renderer's shadow rays through glass rely on two things a filter sees: each lane's own ray,
// passed as packet.ray[i] (so that a filter can tell lanes apart), and, when it refuses every hit,
// every face the ray meets in its interval, with the t of the closest-hit query (tracer.cpp,
// Tracer::notesTransparent). Both checked against the brute-force loop, for every accelerator.
TEST(PacketQueryProperty, FiltersRefusingEveryHitSeeEachLanesOwnRayAndEveryFaceOnIt) {
  const Soup soup = test::sphere(24, 32, {2, 2, 2}, 1.5f);
  const Accelerator naive = Accelerator::build(soup.positions, soup.faces, AccelKind::Naive);
  const KdTree tree = KdTree::buildSah(soup.positions, soup.faces);
  std::mt19937 rng(11);
  std::vector<TestRay> rays = test::adversarialRays(soup, tree, rng, 1000);
  const std::vector<TestRay> coherent = coherentRays(soup, tree, rng);
  rays.insert(rays.end(), coherent.begin(), coherent.end());
  // Faces seen per lane, as (face, t bits); the lane is where the ray sits in `rays`.
  struct Seen {
    const Ray* rays;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> lanes[kPacketSize];
    bool foreignRay = false;
  };
  auto refuseAll = [](const void* context, const Ray& ray, std::uint32_t face, float t) {
    auto& seen = *static_cast<Seen*>(const_cast<void*>(context));
    const std::ptrdiff_t lane = &ray - seen.rays;
    if (lane < 0 || lane >= kPacketSize) {
      seen.foreignRay = true;
    } else {
      seen.lanes[lane].emplace_back(face, std::bit_cast<std::uint32_t>(t));
    }
    return false;
  };
  // Every face the ray's line meets in (tMin, tMax), from the brute-force loop (one face refused at
  // a time until nothing is left).
  auto everyFace = [&](const Ray& ray, float tMin, float tMax) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> faces;
    const HitFilter notYetSeen{
        &faces, [](const void* c, const Ray&, std::uint32_t face, float) {
          const auto& seen = *static_cast<const std::vector<std::pair<std::uint32_t, std::uint32_t>>*>(c);
          return std::none_of(seen.begin(), seen.end(), [&](const auto& f) { return f.first == face; });
        }};
    Hit hit;
    while (naive.intersect(ray, tMin, tMax, notYetSeen, hit))
      faces.emplace_back(hit.face, std::bit_cast<std::uint32_t>(hit.t));
    std::sort(faces.begin(), faces.end());
    return faces;
  };
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeMedian, AccelKind::Naive}) {
    SCOPED_TRACE(std::string(accelKindName(kind)));
    const Accelerator accel = Accelerator::build(soup.positions, soup.faces, kind);
    int lanesWithFaces = 0;
    for (const auto& [packet, active] : packetsOf(rays, true)) {
      Seen seen;
      seen.rays = packet.ray;
      EXPECT_EQ(accel.occluded(packet, active, HitFilter{&seen, refuseAll}), 0u);
      ASSERT_FALSE(seen.foreignRay);
      for (int i = 0; i < kPacketSize; ++i) {
        auto& lane = seen.lanes[i];
        if ((active >> i & 1u) == 0) {
          EXPECT_TRUE(lane.empty()) << "inactive lane " << i;
          continue;
        }
        std::sort(lane.begin(), lane.end());
        lane.erase(std::unique(lane.begin(), lane.end()), lane.end());
        // A quad's halves are one face: the loop above counts the face once, at its closest t.
        lane.erase(std::unique(lane.begin(), lane.end(),
                               [](const auto& a, const auto& b) { return a.first == b.first; }),
                   lane.end());
        const auto expected = everyFace(packet.ray[i], packet.tMin[i], packet.tMax[i]);
        EXPECT_EQ(lane, expected) << "lane " << i;
        lanesWithFaces += !expected.empty();
      }
    }
    EXPECT_GT(lanesWithFaces, 500);
  }
}

TEST(PacketQueryProperty, WatertightRaysFromInsideAllHitAsSingleRays) {
  // The rays of the watertight property test: from near the centre of closed gmsh meshes to their
  // vertices and edges.
  for (const std::string file : {"render/sphere_fine.msh", "render/ball.msh", "msh/cube_tet4_v41_bin.msh"}) {
    SCOPED_TRACE(file);
    const Soup mesh = loadFixture(file);
    const KdTree tree = KdTree::buildSah(mesh.positions, mesh.faces);
    std::vector<TestRay> rays;
    for (const Ray& ray : test::raysAtCornersAndEdges(mesh.positions, mesh.faces)) {
      TestRay r;
      r.ray = ray;
      r.tMax = 2.0f;
      rays.push_back(r);
    }
    const Bvh bvh = Bvh::build(mesh.positions, mesh.faces);
    auto check = [&](const auto& accel, bool bySigns) {
      SCOPED_TRACE(accel.stats().kind);
      const auto packets = packetsOf(rays, bySigns);
      int misses = 0, unblocked = 0, lanes = 0;
      for (const auto& [packet, active] : packets) {
        Hit hits[kPacketSize];
        misses += std::popcount(active & ~accel.intersect(packet, active, std::span<Hit, kPacketSize>(hits)));
        unblocked += std::popcount(active & ~accel.occluded(packet, active));
        lanes += std::popcount(active);
      }
      EXPECT_EQ(misses, 0) << "of " << lanes << " lanes";
      EXPECT_EQ(unblocked, 0) << "of " << lanes << " lanes";
      int hits = 0;
      EXPECT_EQ(countDifferences(accel, packets, hits), 0);
    };
    for (const bool bySigns : {true, false}) {
      check(tree, bySigns);
      check(bvh, bySigns);
    }
  }
}

}  // namespace
}  // namespace lancer
