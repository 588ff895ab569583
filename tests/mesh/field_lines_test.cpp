// Field lines against closed forms on gmsh-made volumes (scripts/make_volume_fixtures.sh): in the
// uniform field u = (1, 2, 3) of a hexahedral cube a line is the straight segment through its seed
// from boundary to boundary; in a rotation about the cube's axis (linear: the mesh carries it
// exactly) a helix of constant radius; in the field of a point dipole p = z at c, a line keeps
// r / sin^2(theta) (spherical coordinates about c) constant, within the error of the field's linear
// interpolation on the mesh.
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
  const std::vector<Vec3d> seeds = {Vec3d{0.5, 0.5, 0.5} - volume.origin,
                                    Vec3d{0.3, 0.6, 0.2} - volume.origin};
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

// A vector field given at the nodes of the cube by `at` (world coordinates).
template <typename Field>
VolumeField nodeField(const VolumeMesh& volume, Field at) {
  VolumeField field;
  field.name = "v";
  field.components = 3;
  for (const Vec3& node : volume.nodes) {
    const Vec3d v = at(toDouble(node) + volume.origin);
    field.values.insert(field.values.end(), {float(v.x), float(v.y), float(v.z)});
  }
  return field;
}

TEST(FieldLines, ARotationsLinesAreCirclesToTheIntegratorsTolerance) {
  // Linear, so the mesh carries it exactly: what is left is the integrator's error.
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const VolumeField rotation = nodeField(volume, [](const Vec3d& p) {
    return Vec3d{-(p.y - 0.5), p.x - 0.5, 0.1};
  });
  const std::vector<Vec3d> seeds = {Vec3d{0.8, 0.5, 0.05} - volume.origin,
                                    Vec3d{0.5, 0.3, 0.1} - volume.origin};
  FieldLineSettings settings;
  settings.backward = false;
  settings.tolerance = 1e-7;  // each step's error: the line's is at most their sum
  const std::vector<FieldLine> lines = traceFieldLines(volume, locator, rotation, seeds, settings);
  double worst = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const FieldLine& line = lines[l];
    ASSERT_GT(line.points.size(), 10U);
    EXPECT_EQ(line.forwardEnd, FieldLineEnd::kBoundary);  // it climbs out through the top
    const Vec3d seed = seeds[l] + volume.origin;
    const double radius = std::hypot(seed.x - 0.5, seed.y - 0.5);
    for (const Vec3d& local : line.points) {
      const Vec3d p = local + volume.origin;
      worst = std::max(worst, std::abs(std::hypot(p.x - 0.5, p.y - 0.5) - radius));
      // A helix: the height grows with the angle turned, 0.1 per radian at unit speed in the plane.
    }
  }
  RecordProperty("worst_radius_error", std::to_string(worst));
  EXPECT_LT(worst, 1e-5);
}

TEST(FieldLines, APointDipolesLinesKeepTheirInvariant) {
  // The dipole p = z at c below the cube, far enough that the mesh's linear interpolation is close to
  // it (its error, not the integrator's, is what remains): r / sin^2(theta) is constant on a line.
  const VolumeMesh& volume = *hexCube().volume;
  const VolumeLocator locator(volume);
  const Vec3d centre{0.5, 0.5, -1.5};
  const VolumeField dipole = nodeField(volume, [&](const Vec3d& p) {
    const Vec3d d = p - centre;
    const double r = length(d);
    const Vec3d unit = d * (1 / r);
    return (unit * (3 * unit.z) - Vec3d{0, 0, 1}) * (1 / (r * r * r));
  });
  std::vector<Vec3d> seeds;
  for (const Vec3d& seed : {Vec3d{0.1, 0.5, 0.5}, Vec3d{0.2, 0.5, 0.6}, Vec3d{0.85, 0.5, 0.4},
                            Vec3d{0.9, 0.45, 0.7}, Vec3d{0.5, 0.1, 0.5}})
    seeds.push_back(seed - volume.origin);
  const std::vector<FieldLine> lines = traceFieldLines(volume, locator, dipole, seeds, FieldLineSettings{});
  double worst = 0;
  for (const FieldLine& line : lines) {
    ASSERT_GT(line.points.size(), 5U);
    const auto invariant = [&](const Vec3d& local) {
      const Vec3d d = local + volume.origin - centre;
      const double r = length(d);
      return r / ((d.x * d.x + d.y * d.y) / (r * r));
    };
    const double seedValue = invariant(line.points[line.seedIndex]);
    for (const Vec3d& p : line.points) worst = std::max(worst, std::abs(invariant(p) / seedValue - 1));
  }
  RecordProperty("worst_relative_drift", std::to_string(worst));
  EXPECT_LT(worst, 0.05);  // 0.035 measured: the interpolation on 1/6-wide cells
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
