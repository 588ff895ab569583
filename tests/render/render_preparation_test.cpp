// prepareRender, the one preparation of the CLI and the Python module: its steps and their order
// (overrides before the memory check, a quick look's own mesh instead of a file), what it returns
// for a frame, and the memory check's message at the scene's path.
#include "lancer/render/render_preparation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/util/memory_budget.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

const std::string kBracket = std::string(LANCER_TEST_DATA_DIR) + "/render/bracket_coarse.msh";

RenderRequest quickLookRequest() {
  RenderRequest request;
  request.quickLookMesh = readMsh(kBracket);
  request.description = quickLookScene(kBracket, *request.quickLookMesh, std::nullopt);
  request.stages.add("read", 0.25);
  return request;
}

TEST(RenderPreparation, AQuickLookIsPreparedFromItsOwnMeshWithTheOverridesApplied) {
  RenderRequest request = quickLookRequest();
  request.overrides.width = 48;
  request.overrides.height = 32;
  const std::size_t faces = request.quickLookMesh->faces.size();
  const PreparedRender prepared = prepareRender(std::move(request));
  EXPECT_EQ(prepared.settings().width, 48);
  EXPECT_EQ(prepared.settings().height, 32);
  EXPECT_EQ(prepared.scene.geometry.faces.size(), faces);
  // The caller's stages come first and count as load time; the accelerator build comes last.
  ASSERT_GE(prepared.stages.stages.size(), 2u);
  EXPECT_EQ(prepared.stages.stages.front().name, "read");
  EXPECT_EQ(prepared.stages.stages.back().name, "accel build");
  EXPECT_GE(prepared.loadSeconds, 0.25);
  EXPECT_EQ(prepared.stages.stages.back().seconds, prepared.buildSeconds);
  const Image image = prepared.renderer().renderImage(RenderOptions{});
  EXPECT_EQ(image.width(), 48);
  EXPECT_EQ(image.height(), 32);
}

TEST(RenderPreparation, TheAcceleratorIsAStepOfItsOwn) {
  const PreparedRender prepared = prepareRender(quickLookRequest());
  const Accelerator again = buildAccelerator(prepared.scene, AccelKind::Naive, 1);
  const Ray ray = prepared.camera.generateRay(0.5f * static_cast<float>(prepared.settings().width),
                                              0.5f * static_cast<float>(prepared.settings().height));
  constexpr float kFar = std::numeric_limits<float>::infinity();
  Hit a, b;
  ASSERT_TRUE(prepared.accelerator.intersect(ray, 0, kFar, a));
  ASSERT_TRUE(again.intersect(ray, 0, kFar, b));
  EXPECT_EQ(a.face, b.face);
  EXPECT_EQ(a.t, b.t);
}

// Rays through a grid of pixels hit the same faces at the same distances, with the same
// barycentrics (relative to the faces' winding), on `prepared`'s accelerator and on a reference
// built afterwards over the prepared scene's faces.
void expectSameHitsAsASerialBuild(const PreparedRender& prepared) {
  const Accelerator serial = buildAccelerator(prepared.scene, AccelKind::Naive, 1);
  constexpr float kFar = std::numeric_limits<float>::infinity();
  int hits = 0;
  for (int y = 0; y < prepared.settings().height; y += 3)
    for (int x = 0; x < prepared.settings().width; x += 3) {
      const Ray ray = prepared.camera.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
      Hit a, b;
      const bool hitA = prepared.accelerator.intersect(ray, 0, kFar, a);
      ASSERT_EQ(hitA, serial.intersect(ray, 0, kFar, b)) << x << ", " << y;
      if (!hitA) continue;
      ++hits;
      EXPECT_EQ(a.face, b.face) << x << ", " << y;
      EXPECT_EQ(a.t, b.t) << x << ", " << y;
      EXPECT_EQ(a.b1, b.b1) << x << ", " << y;
      EXPECT_EQ(a.b2, b.b2) << x << ", " << y;
    }
  EXPECT_GT(hits, 20);
}

TEST(RenderPreparation, TheAcceleratorBuiltAlongsideTheSceneIsTheOneASerialBuildGives) {
  RenderRequest request = quickLookRequest();
  request.overrides.width = 64;
  request.overrides.height = 48;
  request.threads = 2;
  request.buildAlongside = true;
  const PreparedRender prepared = prepareRender(std::move(request));
  expectSameHitsAsASerialBuild(prepared);
  // The stage is the build's own time; what it adds to the load is no more.
  EXPECT_GE(prepared.stages.stages.back().seconds, 0.0);
  EXPECT_GE(prepared.buildSeconds, 0.0);
}

TEST(RenderPreparation, AMeshWoundInwardIsBuiltAgainOverItsTurnedFaces) {
  // Every face wound the other way: orientation turns them all back after the early build
  // started over them, whose triangles then hold the wrong corner order.
  RenderRequest request = quickLookRequest();
  for (MeshFace& face : request.quickLookMesh->faces) std::swap(face.vertex[1], face.vertex[2]);
  request.buildAlongside = true;
  request.overrides.width = 64;
  request.overrides.height = 48;
  const PreparedRender prepared = prepareRender(std::move(request));
  const Mesh original = readMsh(kBracket);
  ASSERT_EQ(prepared.scene.geometry.faces.size(), original.faces.size());
  for (std::size_t f = 0; f < original.faces.size(); ++f)
    ASSERT_EQ(prepared.scene.geometry.faces[f].vertex[1], original.faces[f].vertex[1]) << f;
  expectSameHitsAsASerialBuild(prepared);
}

// NaN-aware: the arrays hold NaN for "not coloured".
void expectSameValues(const std::vector<float>& a, const std::vector<float>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(std::isnan(a[i]) && std::isnan(b[i]))) {
      ASSERT_EQ(a[i], b[i]) << what << " " << i;
    }
}

TEST(RenderPreparation, AColouredMeshWithIsolinesIsTheSameSceneWithTheBuildAlongside) {
  // The annotations are placed by the scene's vertex and face bases, which the build alongside must
  // not move (it places the mesh's positions and faces in the scene first): the scene matches the
  // one prepared without it (keepMeshes builds no accelerator alongside).
  auto prepare = [](bool keepMeshes) {
    const std::string path = test::dataFile("getdp/magnet_v2_az.pos");
    RenderRequest request;
    request.quickLookMesh = readMsh(path);
    request.description = quickLookScene(path, *request.quickLookMesh);
    ColorBy colorBy;
    colorBy.field = "az";
    request.description.meshes[0].colorBy = colorBy;
    request.overrides.width = 32;
    request.overrides.height = 24;
    request.overrides.isolines = 6;
    request.keepMeshes = keepMeshes;
    request.buildAlongside = !keepMeshes;
    return prepareRender(std::move(request));
  };
  const PreparedRender alongside = prepare(false);
  const PreparedRender serial = prepare(true);
  const Scene& a = alongside.scene;
  const Scene& b = serial.scene;
  ASSERT_EQ(a.geometry.faces.size(), b.geometry.faces.size());
  EXPECT_EQ(a.geometry.positions.size(), b.geometry.positions.size());
  EXPECT_EQ(a.appearance.faceMaterial, b.appearance.faceMaterial);
  EXPECT_EQ(a.appearance.faceOuterMaterial, b.appearance.faceOuterMaterial);
  ASSERT_TRUE(a.fieldColors && b.fieldColors);
  EXPECT_EQ(a.fieldColors->faceColorMap, b.fieldColors->faceColorMap);
  expectSameValues(a.fieldColors->vertexFieldT, b.fieldColors->vertexFieldT, "vertexFieldT");
  expectSameValues(a.fieldColors->faceFieldT, b.fieldColors->faceFieldT, "faceFieldT");
  expectSameValues(a.fieldColors->cornerFieldT, b.fieldColors->cornerFieldT, "cornerFieldT");
  const std::vector<float>& t =
      a.fieldColors->vertexFieldT.empty() ? a.fieldColors->cornerFieldT : a.fieldColors->vertexFieldT;
  EXPECT_TRUE(std::any_of(t.begin(), t.end(), [](float v) { return !std::isnan(v); }));
  ASSERT_TRUE(a.isolines && b.isolines);
  EXPECT_EQ(a.isolines->faceStyle, b.isolines->faceStyle);
  expectSameValues(a.isolines->vertexValue, b.isolines->vertexValue, "isoline vertexValue");
  expectSameValues(a.isolines->cornerValue, b.isolines->cornerValue, "isoline cornerValue");
  expectSameHitsAsASerialBuild(alongside);
}

TEST(RenderPreparation, ImagesRenderedInBandsNeedAFewBandsWhateverTheirHeight) {
  RenderSettings settings;
  settings.width = 1000;
  settings.height = 100000;
  const std::uint64_t whole = imageMemoryBytes(settings, 2, ImageBuffer::Whole);
  EXPECT_EQ(whole, std::uint64_t{1000} * 100000 * (sizeof(Rgba) + 4));
  EXPECT_LT(imageMemoryBytes(settings, 2, ImageBuffer::Bands), whole / 100);
  const std::uint64_t bands = imageMemoryBytes(settings, 2, ImageBuffer::Bands);
  settings.height = 200000;
  EXPECT_EQ(imageMemoryBytes(settings, 2, ImageBuffer::Bands), bands);
}

TEST(RenderPreparation, AnImageOverTheBudgetIsAnErrorAtTheScenesPathBeforeAnyMeshIsBuilt) {
  const std::uint64_t budget = memoryBudget();
  setMemoryBudget(std::uint64_t{1} << 20);
  RenderRequest request = quickLookRequest();
  request.overrides.width = request.overrides.height = 4000;
  request.imageBuffer = [](const RenderSettings&) { return ImageBuffer::Whole; };
  const std::string message = test::messageOf([&] { prepareRender(std::move(request)); });
  setMemoryBudget(budget);
  EXPECT_NE(message.find(kBracket), std::string::npos) << message;
  EXPECT_NE(message.find("a 4000x4000 image needs"), std::string::npos) << message;
  EXPECT_NE(message.find("--max-memory"), std::string::npos) << message;
}

}  // namespace
}  // namespace lancer
