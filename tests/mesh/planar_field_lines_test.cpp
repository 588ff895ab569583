// Field lines across flat 2D meshes (mesh/volume/planar_domain.hpp) against closed forms, on the
// gmsh-made unit square (tests/data/fields, tests/data/msh): in the field (x, 2y) (the fixture's
// (x, 2y, 2) projected into the plane) a line keeps y / x^2 constant; in a rotation about the
// square's centre a line is a circle. Both fields are linear, so the triangles carry them exactly
// and what is left is the integrator's error. The same on quads, and on the square turned out of
// the xy plane.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/volume/planar_domain.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// The unit square of triangles with the node field "temperature" = (x, 2y, 2).
Mesh vectorSquare() { return readMsh(test::dataFile("fields/node_vector_v41_bin.msh")); }

// A node field "v" on `mesh` given by `at` (world coordinates).
template <typename Field>
void addNodeField(Mesh& mesh, Field at) {
  MeshField field;
  field.name = "v";
  field.components = 3;
  for (const Vec3& position : mesh.positions) {
    const Vec3d v = at(toDouble(position) + mesh.origin);
    field.values.insert(field.values.end(), {float(v.x), float(v.y), float(v.z)});
  }
  mesh.fields.push_back(field);
}

const VolumeField& onlyStep(const PlanarDomain& domain, const char* name) {
  const VolumeField* field = domain.volume.findField(name, 0);
  EXPECT_NE(field, nullptr);
  return *field;
}

std::vector<FieldLine> trace(const PlanarDomain& domain, const VolumeField& given, std::vector<Vec3d> seeds,
                             FieldLineSettings settings = {}) {
  VolumeField field = given;
  projectIntoPlane(field, domain.normal);
  settings.cellSize = domain.cellSize;
  const VolumeLocator locator(domain.volume);
  for (Vec3d& seed : seeds) seed = ontoPlane(domain, seed - domain.volume.origin);
  return traceFieldLines(domain.volume, locator, field, seeds, settings);
}

TEST(PlanarFieldLines, TheSquareIsFlatAndItsPlaneIsZ) {
  const Mesh square = vectorSquare();
  const PlaneFit fit = fitPlane(square);
  EXPECT_TRUE(fit.flat());
  EXPECT_NEAR(fit.normal.z, 1.0, 1e-12);
  EXPECT_NEAR(fit.diagonal, std::sqrt(2.0), 1e-6);
  const PlanarDomain domain = planarDomain(square, fit);
  EXPECT_EQ(domain.volume.cellCount(), square.faces.size());
  EXPECT_EQ(domain.volume.nodes.size(), 2 * 25U);  // 5 x 5 vertices, two layers
  EXPECT_NEAR(domain.cellSize, std::sqrt(1.0 / 32), 1e-9);
}

TEST(PlanarFieldLines, ALinesOfXAnd2YKeepYOverXSquared) {
  const PlanarDomain domain = [] {
    const Mesh square = vectorSquare();
    return planarDomain(square, fitPlane(square));
  }();
  FieldLineSettings settings;
  settings.tolerance = 1e-8;
  const std::vector<FieldLine> lines =
      trace(domain, onlyStep(domain, "temperature"), {{0.5, 0.25, 0}, {0.3, 0.6, 0}}, settings);
  double worst = 0;
  for (const FieldLine& line : lines) {
    ASSERT_GT(line.points.size(), 5U);
    EXPECT_EQ(line.forwardEnd, FieldLineEnd::kBoundary);
    const Vec3d seed = line.points[line.seedIndex] + domain.volume.origin;
    const double c = seed.y / (seed.x * seed.x);
    for (const Vec3d& local : line.points) {
      const Vec3d p = local + domain.volume.origin;
      EXPECT_NEAR(p.z, 0.0, 1e-9);  // on the plane, though the field has z = 2
      if (p.x > 0.05) worst = std::max(worst, std::abs(p.y - c * p.x * p.x));
    }
    // Forward, out through x = 1 or y = 1.
    const Vec3d end = line.points.back() + domain.volume.origin;
    EXPECT_LT(std::min(1 - end.x, 1 - end.y), 1e-3) << end.x << " " << end.y;
  }
  RecordProperty("worst_offset", std::to_string(worst));
  EXPECT_LT(worst, 1e-5);
}

// The rotation about (0.5, 0.5) in the square's plane, and the circles it makes.
void expectCircles(Mesh square, double tolerance) {
  addNodeField(square, [](const Vec3d& p) { return Vec3d{-(p.y - 0.5), p.x - 0.5, 0.0}; });
  const PlanarDomain domain = planarDomain(square, fitPlane(square));
  FieldLineSettings settings;
  settings.backward = false;
  settings.maxLength = 2 * std::numbers::pi * 0.3;  // once round
  settings.tolerance = 1e-8;
  const std::vector<FieldLine> lines = trace(domain, onlyStep(domain, "v"), {{0.8, 0.5, 0}}, settings);
  ASSERT_GT(lines[0].points.size(), 20U);
  EXPECT_EQ(lines[0].forwardEnd, FieldLineEnd::kLength);
  double worst = 0, turned = 0;
  for (std::size_t i = 0; i < lines[0].points.size(); ++i) {
    const Vec3d p = lines[0].points[i] + domain.volume.origin;
    worst = std::max(worst, std::abs(std::hypot(p.x - 0.5, p.y - 0.5) - 0.3));
    if (i > 0) {
      const Vec3d q = lines[0].points[i - 1] + domain.volume.origin;
      turned += std::remainder(std::atan2(p.y - 0.5, p.x - 0.5) - std::atan2(q.y - 0.5, q.x - 0.5),
                               2 * std::numbers::pi);
    }
  }
  EXPECT_LT(worst, tolerance);
  // Anticlockwise, about once round (the length counts each step's chord, a little short of its arc).
  EXPECT_GT(turned, 0.99 * 2 * std::numbers::pi);
  EXPECT_LT(turned, 1.2 * 2 * std::numbers::pi);
}

TEST(PlanarFieldLines, ARotationsLinesAreCirclesOnTriangles) {
  expectCircles(readMsh(test::dataFile("msh/square_tri3_v41_bin.msh")), 1e-5);
}

TEST(PlanarFieldLines, ARotationsLinesAreCirclesOnQuads) {
  expectCircles(readMsh(test::dataFile("msh/square_quad4_v41_bin.msh")), 1e-5);
}

TEST(PlanarFieldLines, ATiltedSquareKeepsItsLinesInItsPlane) {
  // The square turned 30 degrees about x and moved: its plane's normal is (0, -sin 30, cos 30).
  Mesh square = vectorSquare();
  const double angle = std::numbers::pi / 6;
  const auto turn = [&](const Vec3d& p) {
    return Vec3d{p.x + 2, p.y * std::cos(angle) - p.z * std::sin(angle) - 1,
                 p.y * std::sin(angle) + p.z * std::cos(angle) + 3};
  };
  for (Vec3& position : square.positions)
    position = toFloat(turn(toDouble(position) + square.origin) - square.origin);
  square.fields.clear();
  // The rotation about the square's centre, turned with it, plus a part along the normal that the
  // projection takes off.
  const Vec3d centre = turn({0.5, 0.5, 0});
  const Vec3d normal{0, -std::sin(angle), std::cos(angle)};
  addNodeField(square, [&](const Vec3d& p) { return cross(normal, p - centre) + normal * 3.0; });
  const PlaneFit fit = fitPlane(square);
  ASSERT_TRUE(fit.flat());
  EXPECT_LT(length(fit.normal - normal), 1e-6);
  const PlanarDomain domain = planarDomain(square, fit);
  FieldLineSettings settings;
  settings.backward = false;
  settings.maxLength = 2 * std::numbers::pi * 0.3;
  settings.tolerance = 1e-8;
  const std::vector<FieldLine> lines = trace(domain, onlyStep(domain, "v"), {turn({0.8, 0.5, 0})}, settings);
  ASSERT_GT(lines[0].points.size(), 20U);
  for (const Vec3d& local : lines[0].points) {
    const Vec3d p = local + domain.volume.origin;
    EXPECT_NEAR(dot(p - centre, normal), 0.0, 1e-6);
    EXPECT_NEAR(length(p - centre), 0.3, 1e-5);
  }
  // Automatic seeds find the tilted square, every one on it.
  const VolumeLocator locator(domain.volume);
  const std::vector<Vec3d> seeds = automaticPlanarSeeds(domain, locator, 10);
  ASSERT_EQ(seeds.size(), 10U);
  for (const Vec3d& seed : seeds) EXPECT_NEAR(dot(seed + domain.volume.origin - centre, normal), 0.0, 1e-6);
}

TEST(PlanarFieldLines, LiftingPutsTheLinesOnTheirSideOfThePlane) {
  const Mesh square = vectorSquare();
  const PlanarDomain domain = planarDomain(square, fitPlane(square));
  std::vector<FieldLine> lines = trace(domain, onlyStep(domain, "temperature"), {{0.5, 0.25, 0}});
  liftOntoPlane(lines, domain, -0.01);
  for (const Vec3d& p : lines[0].points) EXPECT_NEAR(p.z + domain.volume.origin.z, -0.01, 1e-9);
}

TEST(PlanarFieldLines, ASphereIsNotFlat) {
  const PlaneFit fit = fitPlane(readMsh(test::dataFile("msh/sphere_v41_bin.msh")));
  EXPECT_FALSE(fit.flat());
  EXPECT_GT(fit.farthest, 0.1 * fit.diagonal);
}

}  // namespace
}  // namespace lancer
