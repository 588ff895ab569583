// prepareRender, the one preparation of the CLI and the Python module: its steps and their order
// (overrides before the memory check, a quick look's own mesh instead of a file), what it returns
// for a frame, and the memory check's message at the scene's path.
#include "lancer/render/render_preparation.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/quick_look.hpp"
#include "lancer/util/memory_budget.hpp"
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
