// Physical groups as gmsh means them, on files gmsh wrote (tests/data/reader/two_plates_groups.geo,
// made by scripts/make_reader_fixtures.sh): the left square is in "left" (1) and "both" (2), the right
// one in "both" and "right_flipped" (3), which takes it reversed (MSH 4.1 writes -3, MSH 2 a copy
// with reversed nodes). Every format reads the same faces and groups.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/mesh_stats.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

std::string readerFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/reader/" + name;
}

constexpr const char* kTwoPlates[] = {"two_plates_groups_v41_ascii.msh", "two_plates_groups_v41_bin.msh",
                                      "two_plates_groups_v22_ascii.msh", "two_plates_groups_v22_bin.msh"};

// Which square a face lies in: its first vertex's x (the left square spans 0..1, the right 2..3).
bool onLeft(const Mesh& mesh, std::size_t f) { return mesh.worldPosition(mesh.faces[f].vertex[0]).x < 1.5; }

TEST(MshPhysicalGroups, AFaceIsInEveryGroupOfItsEntityAndANegativeTagIsTheGroup) {
  const Mesh reference = readMsh(readerFixture(kTwoPlates[0]));
  for (const char* file : kTwoPlates) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(readerFixture(file));
    // MSH 2's per-group copies (one reversed) are one face each: as many faces as MSH 4.1.
    ASSERT_EQ(mesh.faceCount(), reference.faceCount());
    std::size_t left = 0;
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      const bool isLeft = onLeft(mesh, f);
      left += isLeft;
      EXPECT_EQ(mesh.faceInPhysicalGroup(f, 1), isLeft);
      EXPECT_TRUE(mesh.faceInPhysicalGroup(f, 2));
      EXPECT_EQ(mesh.faceInPhysicalGroup(f, 3), !isLeft);
      EXPECT_FALSE(mesh.faceInPhysicalGroup(f, -3));
      for (const std::int32_t tag : mesh.facePhysicalTag) EXPECT_GT(tag, 0);
    }
    EXPECT_GT(left, 0u);
    EXPECT_LT(left, mesh.faceCount());
    // The groups, once each, with their names; no group -3.
    ASSERT_EQ(mesh.physicalGroups.size(), 3u);
    EXPECT_EQ(mesh.physicalGroups[0].name, "left");
    EXPECT_EQ(mesh.physicalGroups[1].name, "both");
    EXPECT_EQ(mesh.physicalGroups[2].tag, 3);
    EXPECT_EQ(mesh.physicalGroups[2].name, "right_flipped");
    // info's counts: every face under each of its groups.
    const MeshStats stats = computeMeshStats(mesh);
    EXPECT_EQ(stats.facesByPhysicalTag.at(1), left);
    EXPECT_EQ(stats.facesByPhysicalTag.at(2), mesh.faceCount());
    EXPECT_EQ(stats.facesByPhysicalTag.at(3), mesh.faceCount() - left);
    EXPECT_EQ(stats.facesByPhysicalTag.count(-3), 0u);
  }
}

TEST(MshPhysicalGroups, TheCopyOfAReversedGroupDoesNotFlipOrDoubleTheFaces) {
  // The kept faces wind as gmsh meshed the surface (+z for these rectangles), in every format.
  for (const char* file : kTwoPlates) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(readerFixture(file));
    for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
      const Vec3d a = mesh.worldPosition(mesh.faces[f].vertex[0]);
      const Vec3d b = mesh.worldPosition(mesh.faces[f].vertex[1]);
      const Vec3d c = mesh.worldPosition(mesh.faces[f].vertex[2]);
      EXPECT_GT(cross(b - a, c - a).z, 0) << "face " << f;
    }
  }
}

TEST(MshPhysicalGroups, OneGroupPerEntityStoresNothingMore) {
  for (const char* file : {"sphere_v41_ascii.msh", "cube_tet4_v22_ascii.msh", "sphere_part2_v41_bin.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = readMsh(test::mshFixture(file));
    EXPECT_TRUE(mesh.extraPhysicalGroups.empty());
    EXPECT_EQ(mesh.morePhysicalTags(0), nullptr);
  }
  // square.geo puts its surface in "plate" and "everything": one entry for the one entity.
  const Mesh square = readMsh(test::mshFixture("square_tri3_v41_bin.msh"));
  ASSERT_EQ(square.extraPhysicalGroups.size(), 1u);
  EXPECT_EQ(square.extraPhysicalGroups[0].more, std::vector<std::int32_t>{2});
}

}  // namespace
}  // namespace lancer
