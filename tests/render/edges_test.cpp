// Element edges on gmsh meshes: only the true element edges are drawn (no quad diagonals, no edges
// made by splitting second-order elements), at the pixel width asked, in reflections too.
#include <gtest/gtest.h>

#include <algorithm>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr int kSize = 96;

// The unit square of tests/data/geo/square.geo (4 x 4 elements) seen from above, orthographic,
// filling the image with a small margin; red edges 1.5 pixels wide.
SceneDescription topDownEdges() {
  SceneDescription d = test::orthographicView(kSize, kSize, Vec3d{0.5, 0.5, 3}, Vec3d{0.5, 0.5, 0}, 1.2);
  d.render.shading = ShadingMode::Flat;
  d.render.background = {1, 1, 1};  // so that a pixel just outside the square is not "red"
  d.ambient = {1, 1, 1};
  d.materials = {test::ambientOnlyMaterial("white", {1, 1, 1})};
  d.meshes.resize(1);
  d.meshes[0].edges = EdgeSettings{1.5f, {1, 0, 0}, false, 30};
  return d;
}

Image renderTopDown(const std::string& fixture) {
  const SceneDescription d = topDownEdges();
  return test::renderMeshes(d, {readMsh(test::mshFixture(fixture))});
}

// Pixel whose centre is nearest the world point (x, y) of the square; points on the square's
// border are moved a hair inside, where the border's half of the line is drawn.
Rgba pixelAt(const Image& image, double x, double y) {
  const double pixel = 1.2 / kSize;
  x = std::clamp(x, 1e-3, 1 - 1e-3);
  y = std::clamp(y, 1e-3, 1 - 1e-3);
  return image.at(static_cast<int>((x - 0.5) / pixel + kSize / 2.0),
                  static_cast<int>((0.5 - y) / pixel + kSize / 2.0));
}

TEST(Edges, DrawnOnElementEdgesOnlyForEverySquareMesh) {
  for (const char* fixture :
       {"square_tri3_v41_bin.msh", "square_quad4_v41_bin.msh", "square_tri6_v41_bin.msh",
        "square_quad8_v41_bin.msh", "square_quad9_v41_bin.msh"}) {
    const Image image = renderTopDown(fixture);
    // Element edges at multiples of 0.25 are red: pixel centres sit half a pixel off the lines, so
    // a 1.5-pixel line covers them by 3/4 (a little less next to a mid-edge node, where the middle
    // triangle of a split element draws only the line's round end: still over half).
    for (double along : {0.1, 0.37, 0.62, 0.9}) {
      for (double line : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        EXPECT_LT(pixelAt(image, line, along).g, 0.5f) << fixture << " vertical line x=" << line;
        EXPECT_LT(pixelAt(image, along, line).g, 0.5f) << fixture << " horizontal line y=" << line;
      }
    }
    // (0.125, 0.0625) in each cell lies on an edge made by splitting a second-order element (for
    // either diagonal of a triangle pair, and on the midline of a split quad), and 3.5 pixels
    // from every true element edge: nothing may be drawn there.
    for (double x : {0.125, 0.375, 0.625, 0.875})
      for (double y : {0.0625, 0.3125, 0.5625, 0.8125}) EXPECT_EQ(pixelAt(image, x, y).g, 1.0f) << fixture;
  }
  // Quads are primitives: their diagonals (through the cell centres) are never drawn.
  for (const char* fixture : {"square_quad4_v41_bin.msh", "square_quad9_v41_bin.msh"}) {
    const Image image = renderTopDown(fixture);
    for (double x : {0.15, 0.4, 0.65, 0.9})
      for (double y : {0.15, 0.4, 0.65, 0.9}) EXPECT_EQ(pixelAt(image, x, y).g, 1.0f) << fixture;
  }
}

TEST(Edges, SecondOrderMeshesLookLikeTheirLinearMeshes) {
  // gmsh makes the order-2 mesh from the same linear mesh, so with only element edges drawn the
  // pictures must agree: a drawn split edge would differ by whole lines of pixels.
  EXPECT_GT(test::psnr8(renderTopDown("square_tri6_v41_bin.msh"), renderTopDown("square_tri3_v41_bin.msh")),
            40);
  EXPECT_GT(test::psnr8(renderTopDown("square_quad8_v41_bin.msh"), renderTopDown("square_quad4_v41_bin.msh")),
            40);
  EXPECT_GT(test::psnr8(renderTopDown("square_quad9_v41_bin.msh"), renderTopDown("square_quad4_v41_bin.msh")),
            40);
}

TEST(Edges, WidthIsInPixels) {
  // Count the red pixels across one vertical line: about `width` of them (plus the blend).
  for (float width : {1.0f, 3.0f}) {
    SceneDescription d = topDownEdges();
    d.meshes[0].edges->widthPixels = width;
    const Image image = test::renderMeshes(d, {readMsh(test::mshFixture("square_quad4_v41_bin.msh"))});
    const int row = kSize / 2 + 7;
    float coverage = 0;  // summed redness across the x = 0.5 line's neighbourhood
    for (int x = kSize / 2 - 8; x <= kSize / 2 + 8; ++x) coverage += 1.0f - image.at(x, row).g;
    EXPECT_NEAR(coverage, width, 0.35f) << width;
  }
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// Ink of the red line nearest world x along the pixel row through world y: the sum over the row
// of each pixel's coverage 1 - green (white under the line, red on it), within 4 pixels of x.
double inkAcross(const Image& image, double x, double y) {
  const double pixel = 1.2 / kSize;
  const int row = static_cast<int>((0.5 - y) / pixel + kSize / 2.0);
  const double centre = (x - 0.5) / pixel + kSize / 2.0;
  double ink = 0;
  for (int column = static_cast<int>(centre) - 4; column <= static_cast<int>(centre) + 4; ++column)
    ink += 1.0 - image.at(column, row).g;
  return ink;
}

// An element edge on the square's outline is drawn whole, as wide as an interior edge: over the
// background, and over a second surface behind it.
TEST(Edges, OutlineEdgesAreAsWideAsInteriorEdges) {
  for (bool floorBehind : {false, true}) {
    SceneDescription d = topDownEdges();
    d.meshes[0].edges->widthPixels = 3;
    std::vector<Mesh> meshes;
    meshes.push_back(readMsh(test::mshFixture("square_quad4_v41_bin.msh")));
    if (floorBehind) {
      d.meshes.resize(2);  // a white floor without edges, a unit below
      meshes.push_back(test::squareMesh(-1, -1, 2, 2, -1));
    }
    const Image image = test::renderMeshes(d, std::move(meshes));
    for (double y : {0.375, 0.625}) {
      const double interior = inkAcross(image, 0.25, y);
      EXPECT_NEAR(interior, 3.0, 0.05) << "y " << y;
      for (double x : {0.0, 1.0})
        EXPECT_NEAR(inkAcross(image, x, y), interior, 0.05) << "x " << x << " y " << y;
    }
  }
}

}  // namespace
}  // namespace lancer
