// GeometryOverlap: the accelerator's build started by the scene's preparation, used only when it
// ran over the scene's final faces; its error is raised where the caller waits for it.
#include "lancer/scene/geometry_overlap.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace lancer {
namespace {

TEST(GeometryOverlap, ATaskNeverStartedIsNotUsed) {
  bool ran = false;
  GeometryOverlap overlap([&](std::span<const Vec3>, std::span<const MeshFace>) { ran = true; });
  EXPECT_FALSE(overlap.finish());
  EXPECT_FALSE(ran);
}

TEST(GeometryOverlap, TheTaskRunsOverWhatItWasGivenAndIsUsedWhenTheFacesStayed) {
  const std::vector<Vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<MeshFace> faces{MeshFace{{0, 1, 2, kNoVertex}}};
  std::size_t seenVertices = 0, seenFaces = 0;
  GeometryOverlap overlap([&](std::span<const Vec3> p, std::span<const MeshFace> f) {
    seenVertices = p.size();
    seenFaces = f.size();
  });
  overlap.start(positions, faces);
  EXPECT_TRUE(overlap.finish());
  EXPECT_EQ(seenVertices, 3u);
  EXPECT_EQ(seenFaces, 1u);
}

TEST(GeometryOverlap, FacesChangedAfterTheStartAreNotUsedAndTheGivenOnesAreKeptTillTheEnd) {
  const std::vector<Vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<MeshFace> given{MeshFace{{0, 1, 2, kNoVertex}}};
  const MeshFace* data = given.data();
  std::uint32_t secondCorner = 0;
  GeometryOverlap overlap(
      [&](std::span<const Vec3>, std::span<const MeshFace> f) { secondCorner = f[0].vertex[1]; });
  overlap.start(positions, given);
  overlap.facesChanged(std::move(given));  // the array the task reads moves, its bytes stay
  EXPECT_FALSE(overlap.finish());
  EXPECT_EQ(secondCorner, 1u);
  EXPECT_NE(data, nullptr);
}

TEST(GeometryOverlap, TheTasksErrorIsRaisedByFinishAndDroppedByAbandon) {
  const std::vector<Vec3> positions;
  const std::vector<MeshFace> faces;
  GeometryOverlap failing([](std::span<const Vec3>, std::span<const MeshFace>) {
    throw std::runtime_error("out of memory for the tree");
  });
  failing.start(positions, faces);
  EXPECT_THROW(failing.finish(), std::runtime_error);
  GeometryOverlap abandoned([](std::span<const Vec3>, std::span<const MeshFace>) {
    throw std::runtime_error("out of memory for the tree");
  });
  abandoned.start(positions, faces);
  abandoned.abandon();  // no throw
}

}  // namespace
}  // namespace lancer
