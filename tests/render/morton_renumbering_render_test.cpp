// A mesh renumbered in Morton order (mesh/morton_renumbering.hpp) renders the picture its file's
// order gives: only where a ray meets an edge two faces share (which face wins the tie follows the
// order) and in the last bits of smooth normals (summed in another order) may a pixel change. With
// colours from node, element and element-node fields, so that a value put on the wrong vertex,
// face or corner shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "lancer/mesh/morton_renumbering.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/quick_look.hpp"
#include "support/files.hpp"
#include "support/test_images.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// Pixels that differ by more than a step of an 8-bit channel.
int visiblyDifferentPixels(const Image& a, const Image& b) {
  int count = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const Rgba p = a.at(x, y), q = b.at(x, y);
      const float most =
          std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
      count += !(most <= 1.0f / 255.0f);
    }
  return count;
}

void expectSamePicture(const std::string& file, const char* field, std::optional<int> step = {}) {
  const Mesh mesh = readMsh(test::dataFile(file), 1);
  SceneDescription description = quickLookScene(test::dataFile(file), mesh);
  description.render.width = 96;
  description.render.height = 72;
  if (field) {
    ColorBy colorBy;
    colorBy.field = field;
    colorBy.step = step;
    description.meshes.front().colorBy = colorBy;
  }
  Mesh renumbered = mesh;
  renumberInMortonOrder(renumbered, 2);
  const Image before = test::renderMeshes(description, {mesh});
  const Image after = test::renderMeshes(description, {renumbered});
  const int pixels = before.width() * before.height();
  EXPECT_LE(visiblyDifferentPixels(before, after), pixels / 100) << file;
  // The test can fail: the renumbered mesh with its faces' corners in the old order (no field), or
  // with its field values in the old order, is another picture.
  Mesh scrambled = renumbered;
  if (field)
    scrambled.fields = mesh.fields;
  else
    scrambled.faces = mesh.faces;
  EXPECT_GT(visiblyDifferentPixels(before, test::renderMeshes(description, {scrambled})), pixels / 50)
      << file;
}

TEST(MortonRenumberingRender, TheSamePictureExceptAtSharedEdges) {
  expectSamePicture("render/bracket_coarse.msh", nullptr);
}

TEST(MortonRenumberingRender, FieldColoursStayOnTheirVerticesFacesAndCorners) {
  expectSamePicture("results/cantilever.msh", "displacement", 3);  // step 0 is at rest
  expectSamePicture("fields/element_xy_v41_bin.msh", "temperature");
  expectSamePicture("results/cantilever.msh", "stress", 3);
  expectSamePicture("element_node/tet_v41_bin.msh", "jump");
}

// A wavy sheet of n x n squares, two triangles each, numbered row by row (not Morton's order).
Mesh wavySheet(int n) {
  Mesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = static_cast<float>(i) / static_cast<float>(n),
                  y = static_cast<float>(j) / static_cast<float>(n);
      mesh.positions.push_back({x, y, 0.05f * std::sin(12.0f * x) * std::cos(9.0f * y)});
    }
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.faces.push_back(MeshFace{{at(i, j), at(i + 1, j), at(i + 1, j + 1), kNoVertex}});
      mesh.faces.push_back(MeshFace{{at(i, j), at(i + 1, j + 1), at(i, j + 1), kNoVertex}});
    }
  mesh.facePhysicalTag.assign(mesh.faces.size(), 1);
  mesh.faceEntityTag.assign(mesh.faces.size(), 1);
  mesh.faceEdgeMask.assign(mesh.faces.size(), kAllEdges);
  return mesh;
}

TEST(MortonRenumberingRender, APreparedRenderOfALargeMeshIsRenumberedAndTracesTheSamePixels) {
  const Mesh sheet = wavySheet(363);  // 263,538 triangles: just over the threshold
  ASSERT_GE(sheet.faces.size(), kMortonRenumberingMinFaces);
  RenderRequest request;
  request.description = quickLookScene("sheet.msh", sheet);
  request.description.render.width = 64;
  request.description.render.height = 48;
  request.quickLookMesh = sheet;
  request.threads = 2;
  const SceneDescription description = request.description;
  const PreparedRender prepared = prepareRender(std::move(request));
  const auto& stages = prepared.stages.stages;
  EXPECT_TRUE(std::any_of(stages.begin(), stages.end(), [](const auto& s) { return s.name == "renumber"; }));
  // The faces the tracer sees are the sheet's, in another order.
  ASSERT_EQ(prepared.scene.geometry.faces.size(), sheet.faces.size());
  bool reordered = false;
  for (std::size_t f = 0; f < sheet.faces.size() && !reordered; ++f)
    reordered = prepared.scene.geometry.faces[f].vertex[0] != sheet.faces[f].vertex[0];
  EXPECT_TRUE(reordered);

  const Image renumbered = prepared.renderer().renderImage(RenderOptions{});
  const Image fileOrder = test::renderMeshes(description, {sheet});
  EXPECT_LE(visiblyDifferentPixels(renumbered, fileOrder), 64 * 48 / 100);
  // `--pixel` traces one pixel of the prepared render: the value the file's order gives there.
  TraceCounters counters;
  std::uint64_t samples = 0;
  const Rgba pixel = prepared.renderer().renderPixel(32, 24, counters, samples);
  const Rgba expected = fileOrder.at(32, 24);
  EXPECT_NEAR(pixel.r, expected.r, 1e-4f);
  EXPECT_NEAR(pixel.g, expected.g, 1e-4f);
  EXPECT_NEAR(pixel.b, expected.b, 1e-4f);
}

}  // namespace
}  // namespace lancer
