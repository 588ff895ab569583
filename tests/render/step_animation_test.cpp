// Animations over time steps on the gmsh-made cantilever whose displacement is known in closed form
// (scripts/make_result_fixtures.py): the deformed silhouette of every frame, seen from the side, is
// the exact shape at the frame's time, at the steps and between them; frames come in time order;
// colour ranges stay fixed over the animation.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lancer/mesh/msh/stored_steps.hpp"
#include "lancer/render/step_animation.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "support/files.hpp"
#include "support/scoped_env.hpp"
#include "support/test_images.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

constexpr double kLength = 10, kHeight = 1;
constexpr int kWidth = 360, kImageHeight = 200;
constexpr double kViewHeight = 6, kCentreX = 5.25, kCentreY = -0.25;
constexpr double kPixel = kViewHeight / kImageHeight;

double deflection(double x, double t) {
  return t * x * x * (3 * kLength - x) / (2 * kLength * kLength * kLength);
}

// The side view (looking down -z at the beam's face z = 1), the beam warped by its displacement.
SceneDescription sideView(double factor) {
  SceneDescription d =
      test::flatLitOnBlue(test::orthographicView(kWidth, kImageHeight, {kCentreX, kCentreY, 10},
                                                 {kCentreX, kCentreY, 0}, kViewHeight),
                          {5, 5, 20});
  d.materials = {test::matteMaterial("beam", {0.8f, 0.8f, 0.2f}, {0.8f, 0.8f, 0.2f})};
  MeshInstance beam;
  beam.file = test::dataFile("results/cantilever.msh");
  WarpSettings warp;
  warp.field = "displacement";
  warp.factor = factor;
  beam.warp = warp;
  d.meshes.push_back(beam);
  return d;
}

bool isBackground(const Rgba& p) { return p.r < 0.05f && p.g < 0.05f && p.b > 0.9f; }

// For columns across the beam, the top and bottom of the silhouette against y = H - f w, y = -f w.
void expectSilhouette(const Image& image, double t, double factor, const std::string& what) {
  int checked = 0;
  for (int i = 0; i < kWidth; ++i) {
    const double x = kCentreX + (i + 0.5 - kWidth / 2.0) * kPixel;
    if (x < 0.2 || x > kLength - 0.2) continue;
    int top = -1, bottom = -1;
    for (int j = 0; j < kImageHeight; ++j)
      if (!isBackground(image.at(i, j))) (top < 0 ? top = j : 0), bottom = j;
    ASSERT_GE(top, 0) << what << ": column " << i << " is empty";
    const double yTop = kCentreY + (kImageHeight / 2.0 - top) * kPixel;  // upper edge of the first row
    const double yBottom = kCentreY + (kImageHeight / 2.0 - bottom - 1) * kPixel;  // lower edge of the last
    const double w = factor * deflection(x, t);
    EXPECT_NEAR(yTop, kHeight - w, 1.5 * kPixel) << what << ", x = " << x;
    EXPECT_NEAR(yBottom, -w, 1.5 * kPixel) << what << ", x = " << x;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(StepAnimation, EachStepsSilhouetteIsTheExactDeformedShape) {
  SceneDescription description = sideView(1.0);
  std::vector<Mesh> meshes = readSceneMeshes(description);
  AnimationSettings animation;
  animation.overSteps = true;
  StepScenes steps(description, meshes, animation, AccelKind::KdTreeSah, 0);
  ASSERT_EQ(steps.frameCount(), 4);
  EXPECT_EQ(steps.frames().times, (std::vector<double>{0, 0.5, 1, 1.5}));
  EXPECT_EQ(steps.frames().steps, (std::vector<int>{0, 1, 2, 3}));
  for (int k = 0; k < 4; ++k)
    expectSilhouette(steps.render(k, RenderOptions{}), 0.5 * k, 1.0, fmt::format("step {}", k));
  EXPECT_EQ(steps.rebuilds(), 3);
  EXPECT_EQ(steps.updatesInPlace(), 3);  // same faces: each step written over the last
}

// A frame whose scene was written over the previous frame's is the frame built from nothing (an
// animation's first frame always is), to float rounding (the two place the vertices about different
// origins): no pixel differs by more than 1e-3 but for a few on the silhouette.
TEST(StepAnimation, FramesUpdatedInPlaceMatchFramesBuiltAfresh) {
  SceneDescription description = sideView(2.0);
  ColorBy color;
  color.field = "temperature";
  description.meshes[0].colorBy = color;
  description.meshes[0].smoothAngleDegrees = 60;
  std::vector<Mesh> meshes = readSceneMeshes(description);
  AnimationSettings animation;
  animation.overSteps = true;
  animation.framesGiven = true;
  animation.frames = 5;
  StepScenes inPlace(description, meshes, animation, AccelKind::Bvh, 2);
  for (int k = 0; k < 5; ++k) {
    const Image updated = inPlace.render(k, RenderOptions{});
    StepScenes fresh(description, meshes, animation, AccelKind::Bvh, 2);
    const Image built = fresh.render(k, RenderOptions{});
    int visiblyDifferent = 0;
    for (int j = 0; j < updated.height(); ++j)
      for (int i = 0; i < updated.width(); ++i) {
        const Rgba p = updated.at(i, j), q = built.at(i, j);
        visiblyDifferent += std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)}) > 1e-3f;
      }
    EXPECT_LE(visiblyDifferent, 4) << "frame " << k;
    EXPECT_GT(test::differingPixels(updated, StepScenes(description, meshes, animation, AccelKind::Bvh, 2)
                                                 .render((k + 2) % 5, RenderOptions{})),
              1000)
        << "frame " << k << " against another frame";
  }
  EXPECT_EQ(inPlace.updatesInPlace(), 4);
  EXPECT_EQ(inPlace.refits(), 4);
}

TEST(StepAnimation, FramesBetweenStepsBlendLinearlyInTime) {
  SceneDescription description = sideView(2.0);
  std::vector<Mesh> meshes = readSceneMeshes(description);
  AnimationSettings animation;
  animation.overSteps = true;
  animation.framesGiven = true;
  animation.frames = 7;  // t = 0, 0.25, ..., 1.5
  StepScenes steps(description, meshes, animation, AccelKind::KdTreeSah, 0);
  ASSERT_EQ(steps.frameCount(), 7);
  EXPECT_EQ(steps.frames().steps, (std::vector<int>{0, 0, 1, 1, 2, 2, 3}));
  for (int k : {1, 5})
    expectSilhouette(steps.render(k, RenderOptions{}), 0.25 * k, 2.0, fmt::format("frame {}", k));
}

TEST(StepAnimation, ColourRangeIsFixedOverTheFramesUnlessPerStep) {
  SceneDescription description = sideView(1.0);
  ColorBy color;
  color.field = "temperature";
  description.meshes[0].colorBy = color;
  description.meshes[0].warp.reset();
  std::vector<Mesh> meshes = readSceneMeshes(description);
  AnimationSettings animation;
  animation.overSteps = true;
  StepScenes fixed(description, meshes, animation, AccelKind::KdTreeSah, 0);
  const Image first = fixed.render(0, RenderOptions{});
  const Image last = fixed.render(3, RenderOptions{});
  EXPECT_NE(first, last);  // the values moved through the one map
  EXPECT_EQ(fixed.rebuilds(), 1);
  animation.perStepRange = true;
  StepScenes own(description, meshes, animation, AccelKind::KdTreeSah, 0);
  // Each step spans its own [5k, 5k + 2] with the same pattern: every frame looks the same.
  EXPECT_EQ(own.render(0, RenderOptions{}), own.render(3, RenderOptions{}));
}

TEST(StepAnimation, PinnedColoursAndNoViewsAreNotSteps) {
  SceneDescription description = sideView(1.0);
  description.meshes[0].warp.reset();
  ColorBy color;
  color.field = "temperature";
  color.step = 2;
  description.meshes[0].colorBy = color;
  std::vector<Mesh> meshes = readSceneMeshes(description);
  AnimationSettings animation;
  animation.overSteps = true;
  EXPECT_THROW(planStepFrames(description, meshes, animation), InputError);
}

// A result too large to keep in memory leaves its steps in the file (LANCER_STEP_MEMORY_MB = 0
// forces it here): the frames are the same pixels, and each step is read back at most twice (to
// frame the camera over the warped frames, then for its frame), not once per use or per frame.
TEST(StepAnimation, StepsLeftInTheFileMakeTheSameFrames) {
  SceneDescription description = sideView(1.0);
  ColorBy color;
  color.field = "temperature";
  description.meshes[0].colorBy = color;
  AnimationSettings animation;
  animation.overSteps = true;
  animation.framesGiven = true;
  animation.frames = 7;  // blends between the steps too
  std::vector<Mesh> kept = readSceneMeshes(description);
  StepScenes fromMemory(description, kept, animation, AccelKind::Bvh, 0);
  const test::ScopedEnv storeAll("LANCER_STEP_MEMORY_MB", "0");
  std::vector<Mesh> stored = readSceneMeshes(description);
  ASSERT_TRUE(stored[0].fields.front().isStored());
  ASSERT_FALSE(kept[0].fields.front().isStored());
  StepScenes fromFile(description, stored, animation, AccelKind::Bvh, 0);
  for (int k = 0; k < 7; ++k)
    EXPECT_EQ(fromFile.render(k, RenderOptions{}), fromMemory.render(k, RenderOptions{})) << "frame " << k;
  // Four steps of displacement and four of temperature.
  EXPECT_LE(stored[0].fields.front().stored->file->fileReads(), 2u * 8u);
}

}  // namespace
}  // namespace lancer
