// Field lines against closed forms on gmsh-made volumes (scripts/make_volume_fixtures.sh): in the
// uniform field u = (1, 2, 3) of a hexahedral cube a line is the straight segment through its seed
// from boundary to boundary; in the field of a point dipole p = z at c, a line keeps
// r / sin^2(theta) (spherical coordinates about c) constant, within the error of the field's
// trilinear-free (piecewise linear) interpolation on the mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/volume/field_line_tubes.hpp"
#include "lancer/mesh/volume/field_lines.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

const MeshWithVolume& hexCube() {
  static const MeshWithVolume read = readMshWithVolume(test::dataFile("volume/cube_hex.msh"));
  return read;
}

TEST(FieldLines, AUniformFieldGivesStraightLinesFromBoundaryToBoundary) {
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const VolumeField& u = *volume.findField("u", 0);
  const std::vector<Vec3d> seeds = {Vec3d{0.5, 0.5, 0.5} - volume.origin, Vec3d{0.3, 0.6, 0.2} - volume.origin};
  const std::vector<FieldLine> lines = traceFieldLines(volume, locator, u, seeds, FieldLineSettings{});
  const Vec3d direction = normalize(Vec3d{1, 2, 3});
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const FieldLine& line = lines[l];
    ASSERT_GT(line.points.size(), 3U);
    EXPECT_EQ(line.forwardEnd, FieldLineEnd::kBoundary);
    EXPECT_EQ(line.backwardEnd, FieldLineEnd::kBoundary);
    for (const Vec3d& p : line.points) EXPECT_LT(length(cross(p - seeds[l], direction)), 1e-6);
    // Forward along u, each end within a small step of the cube's faces.
    EXPECT_GT(dot(line.points.back() - line.points.front(), direction), 0);
    for (const Vec3d& end : {line.points.front(), line.points.back()}) {
      const Vec3d p = end + volume.origin;
      const double toFace = std::min({p.x, p.y, p.z, 1 - p.x, 1 - p.y, 1 - p.z});
      EXPECT_LT(toFace, 2e-3) << p.x << " " << p.y << " " << p.z;
    }
  }
}

TEST(FieldLines, APointDipolesLinesKeepTheirInvariant) {
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const VolumeField& dipole = *volume.findField("dipole", 0);
  const Vec3d centre{0.5, 0.5, -0.5};
  std::vector<Vec3d> seeds;
  for (int i = 0; i < 5; ++i) seeds.push_back(Vec3d{0.2 + 0.15 * i, 0.45, 0.3} - volume.origin);
  const std::vector<FieldLine> lines = traceFieldLines(volume, locator, dipole, seeds, FieldLineSettings{});
  double worst = 0;
  for (const FieldLine& line : lines) {
    ASSERT_GT(line.points.size(), 5U);
    const auto invariant = [&](const Vec3d& local) {
      const Vec3d d = local + volume.origin - centre;
      const double r = length(d);
      const double sinTheta2 = (d.x * d.x + d.y * d.y) / (r * r);
      return r / sinTheta2;
    };
    const double seedValue = invariant(line.points[line.seedIndex]);
    for (const Vec3d& p : line.points) worst = std::max(worst, std::abs(invariant(p) / seedValue - 1));
  }
  RecordProperty("worst_relative_drift", std::to_string(worst));
  // The field is interpolated linearly on 1/6-wide hexahedra of a 1/r^3 field.
  EXPECT_LT(worst, 0.03);
}

TEST(FieldLines, ASeedOutsideGivesNoLineAndAZeroFieldStops) {
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const std::vector<Vec3d> seeds = {Vec3d{3, 3, 3} - volume.origin};
  const std::vector<FieldLine> lines =
      traceFieldLines(volume, locator, *volume.findField("u", 0), seeds, FieldLineSettings{});
  EXPECT_TRUE(lines[0].points.empty());
  VolumeField zero = *volume.findField("u", 0);
  std::fill(zero.values.begin(), zero.values.end(), 0.0F);
  const std::vector<Vec3d> inside = {Vec3d{0.5, 0.5, 0.5} - volume.origin};
  const std::vector<FieldLine> still = traceFieldLines(volume, locator, zero, inside, FieldLineSettings{});
  EXPECT_EQ(still[0].points.size(), 1U);
  EXPECT_EQ(still[0].forwardEnd, FieldLineEnd::kZeroField);
}

TEST(FieldLines, TheSameLinesOnAnyThreadCount) {
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const std::vector<Vec3d> seeds = automaticSeeds(volume, locator, 40);
  ASSERT_EQ(seeds.size(), 40U);
  FieldLineSettings one, two;
  one.threads = 1;
  two.threads = 2;
  const VolumeField& dipole = *volume.findField("dipole", 0);
  const std::vector<FieldLine> a = traceFieldLines(volume, locator, dipole, seeds, one);
  const std::vector<FieldLine> b = traceFieldLines(volume, locator, dipole, seeds, two);
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].points.size(), b[i].points.size());
    for (std::size_t k = 0; k < a[i].points.size(); ++k) EXPECT_EQ(a[i].points[k].x, b[i].points[k].x);
  }
}

TEST(FieldLines, TubesAreClosedAndCarryTheFields) {
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const std::vector<Vec3d> seeds = {Vec3d{0.5, 0.5, 0.5} - volume.origin};
  const std::vector<FieldLine> lines =
      traceFieldLines(volume, locator, *volume.findField("u", 0), seeds, FieldLineSettings{});
  const Mesh tubes = fieldLineTubes(volume, locator, lines, 0.01, 8);
  const std::size_t points = lines[0].points.size();
  EXPECT_EQ(tubes.positions.size(), points * 8 + 2);
  EXPECT_EQ(tubes.faces.size(), (points - 1) * 8 + 16);
  ASSERT_EQ(tubes.fields.size(), volume.fields.size());
  for (const MeshField& field : tubes.fields) EXPECT_EQ(field.itemCount(), tubes.positions.size());
  // Every ring vertex is the radius away from its line.
  for (std::size_t v = 0; v < 8; ++v)
    EXPECT_NEAR(length(toDouble(tubes.positions[v]) - lines[0].points[0]), 0.01, 1e-6);
}

}  // namespace
}  // namespace lancer
