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
#include "lancer/scene/quick_look.hpp"
#include "support/files.hpp"
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

}  // namespace
}  // namespace lancer
