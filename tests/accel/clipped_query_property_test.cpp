// Property: the clipped queries (per-mesh clip planes, face_clip_sets.hpp) of both kd-tree builds
// and of the brute-force reference answer exactly as the definition: the closest of all triangle
// hits whose face its mesh's planes keep, ties to the lower face; occluded when any kept hit exists.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/scene/face_clip_sets.hpp"
#include "support/accel_test_geometry.hpp"

namespace lancer {
namespace {

using test::Soup;

// Appends `part` to `soup` and returns its faces' run.
FaceClipRange append(Soup& soup, const Soup& part) {
  const auto vertexBase = static_cast<std::uint32_t>(soup.positions.size());
  FaceClipRange range;
  range.faceBegin = static_cast<std::uint32_t>(soup.faces.size());
  soup.positions.insert(soup.positions.end(), part.positions.begin(), part.positions.end());
  for (MeshFace face : part.faces) {
    for (int c = 0; c < face.cornerCount(); ++c) face.vertex[c] += vertexBase;
    soup.faces.push_back(face);
  }
  range.faceEnd = static_cast<std::uint32_t>(soup.faces.size());
  return range;
}

void addPlanes(FaceClipSets& clips, FaceClipRange range, std::vector<ClipPlane> planes) {
  range.planeBegin = static_cast<std::uint32_t>(clips.planes.size());
  for (const ClipPlane& plane : planes) {
    clips.planes.push_back(plane);
    clips.caps.push_back(1);
  }
  range.planeEnd = static_cast<std::uint32_t>(clips.planes.size());
  clips.ranges.push_back(range);
}

// The filter the renderer hands the accelerators for its per-mesh planes (as in Tracer).
HitFilter filterOf(const FaceClipSets& clips) {
  return {&clips, [](const void* c, const Ray& ray, std::uint32_t face, float t) {
            return static_cast<const FaceClipSets*>(c)->keeps(ray, face, t);
          }};
}

// The definition, written without any accelerator: every triangle, keep what the planes keep.
bool closestKept(const Soup& soup, const FaceClipSets& clips, const Ray& ray, float tMin, float tMax,
                 Hit& hit) {
  Hit best;
  for (const PackedTriangle& tri : packTriangles(soup.positions, soup.faces)) {
    const float t = intersectTriangle(tri, ray, tMin, tMax);
    if (t >= 0.0f && clips.keeps(ray, tri.face, t) && closerThan(t, tri.face, best)) best = {t, tri.face};
  }
  if (!best.valid()) return false;
  hit = best;
  return true;
}

// Three meshes: a sphere cut by two planes, a grid box with no planes of its own, a random soup
// cut by one; the sphere sits inside the box, so rays pass removed faces to hit the box behind.
struct ClippedScene {
  Soup soup;
  FaceClipSets clips;
};

ClippedScene threeMeshes() {
  ClippedScene scene;
  std::mt19937 rng(21);
  const FaceClipRange sphere = append(scene.soup, test::sphere(24, 32, {2, 2, 2}, 1.5f));
  append(scene.soup, test::gridBox(4));
  const FaceClipRange soup = append(scene.soup, test::randomSoup(rng, 400));
  addPlanes(scene.clips, sphere, {{{2, 2, 2}, normalize(Vec3{1, 0.3f, 0})}, {{2, 2.5f, 2}, {0, 0, 1}}});
  addPlanes(scene.clips, soup, {{{0.5f, 0.5f, 0.5f}, normalize(Vec3{-1, 1, 1})}});
  return scene;
}

TEST(ClippedQueryProperty, EveryAcceleratorMatchesTheDefinition) {
  const ClippedScene scene = threeMeshes();
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeMedian, AccelKind::Naive}) {
    SCOPED_TRACE(std::string(accelKindName(kind)));
    const Accelerator accel = Accelerator::build(scene.soup.positions, scene.soup.faces, kind);
    std::mt19937 rng(7);
    int failures = 0, hits = 0, passedRemoved = 0;
    for (int i = 0; i < 3000; ++i) {
      // From inside the box; half the rays aimed at a vertex, so many cross edges and pass near
      // the planes' cuts.
      const Vec3 origin = test::randomPoint(rng, {0.05f, 0.05f, 0.05f}, {3.95f, 3.95f, 3.95f});
      const Vec3 target = i % 2 ? scene.soup.positions[rng() % scene.soup.positions.size()]
                                : test::randomPoint(rng, {0, 0, 0}, {4, 4, 4});
      const Ray ray(origin, target - origin);
      const float tMax = i % 3 ? 1e30f : 1.0f;
      Hit expected, actual, unclipped;
      const bool expectHit = closestKept(scene.soup, scene.clips, ray, 0.0f, tMax, expected);
      const bool gotHit = accel.intersect(ray, 0.0f, tMax, filterOf(scene.clips), actual);
      const bool gotOccluded = accel.occluded(ray, 0.0f, tMax, filterOf(scene.clips));
      hits += expectHit;
      if (accel.intersect(ray, 0.0f, tMax, unclipped) && (!expectHit || unclipped.face != expected.face))
        ++passedRemoved;
      const bool same = expectHit == gotHit && gotOccluded == expectHit &&
                        (!expectHit || (expected.face == actual.face && expected.t == actual.t));
      if (!same && ++failures <= 5)
        ADD_FAILURE() << "ray " << i << ": expected " << (expectHit ? std::to_string(expected.face) : "miss")
                      << " got " << (gotHit ? std::to_string(actual.face) : "miss") << " occluded "
                      << gotOccluded;
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, 1000);
    EXPECT_GT(passedRemoved, 200) << "many rays should pass a removed face";
  }
}

TEST(ClippedQueryProperty, CoincidentFacesOfTwoMeshesAtEqualT) {
  // Two copies of one square, meshes A (face 0) and B (face 1); A is removed by its own plane. The
  // unclipped query picks face 0 (tie to the lower face); the clipped one must find face 1 at the
  // same t, which a restart from t would skip.
  Soup soup;
  Soup square;
  square.quad(square.vertex({0, 0, 0}), square.vertex({1, 0, 0}), square.vertex({1, 1, 0}),
              square.vertex({0, 1, 0}));
  const FaceClipRange a = append(soup, square);
  append(soup, square);
  FaceClipSets clips;
  addPlanes(clips, a, {{{0, 0, -1}, {0, 0, 1}}});  // removes z > -1: all of A
  const Ray ray({0.5f, 0.5f, 3}, {0, 0, -1});
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::KdTreeSah, AccelKind::KdTreeMedian, AccelKind::Naive}) {
    const Accelerator accel = Accelerator::build(soup.positions, soup.faces, kind);
    Hit plain, clipped;
    ASSERT_TRUE(accel.intersect(ray, 0.0f, 1e30f, plain));
    EXPECT_EQ(plain.face, 0u);
    ASSERT_TRUE(accel.intersect(ray, 0.0f, 1e30f, filterOf(clips), clipped));
    EXPECT_EQ(clipped.face, 1u);
    EXPECT_EQ(clipped.t, plain.t);
    EXPECT_TRUE(accel.occluded(ray, 0.0f, 1e30f, filterOf(clips)));
    // With B cut too nothing is left: no hit, no shadow.
    FaceClipSets both = clips;
    addPlanes(both, {1, 2, 0, 0}, {{{0, 0, -1}, {0, 0, 1}}});
    EXPECT_FALSE(accel.intersect(ray, 0.0f, 1e30f, filterOf(both), clipped));
    EXPECT_FALSE(accel.occluded(ray, 0.0f, 1e30f, filterOf(both)));
  }
}

TEST(ClippedQueryProperty, RangeOfFindsTheMeshOfAFace) {
  FaceClipSets clips;
  addPlanes(clips, {2, 5, 0, 0}, {{{0, 0, 0}, {1, 0, 0}}});
  addPlanes(clips, {9, 10, 0, 0}, {{{0, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {0, 0, 1}}});
  EXPECT_EQ(clips.rangeOf(0), nullptr);
  EXPECT_EQ(clips.rangeOf(2), &clips.ranges[0]);
  EXPECT_EQ(clips.rangeOf(4), &clips.ranges[0]);
  EXPECT_EQ(clips.rangeOf(5), nullptr);
  EXPECT_EQ(clips.rangeOf(9), &clips.ranges[1]);
  EXPECT_EQ(clips.planesOf(clips.ranges[1]).size(), 2u);
  EXPECT_EQ(clips.rangeOf(10), nullptr);
  EXPECT_TRUE(clips.keeps(Ray({-1, 0, 0}, {1, 0, 0}), 3, 0.5f));   // x = -0.5: kept
  EXPECT_FALSE(clips.keeps(Ray({-1, 0, 0}, {1, 0, 0}), 3, 1.5f));  // x = 0.5: removed
  EXPECT_TRUE(clips.keeps(Ray({-1, 0, 0}, {1, 0, 0}), 7, 1.5f));   // face 7 has no planes
}

}  // namespace
}  // namespace lancer
