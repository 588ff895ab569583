// True times: each step keeps the time its file gives it, repeated or unsorted (GetDP's Newmark
// scheme writes t = 0 twice; its eigenmodes store their frequencies unsorted). Frames over such a
// view fall on its steps, and labels show the steps' own times.
#include <gtest/gtest.h>

#include "lancer/render/step_animation.hpp"
#include "lancer/scene/results/result_keys.hpp"

namespace lancer {
namespace {

// One triangle with the view "u" at the given times, one step each.
Mesh triangleWithTimes(const std::vector<double>& times) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.faces = {MeshFace{{0, 1, 2, kNoVertex}}};
  mesh.facePhysicalTag = {0};
  mesh.faceEntityTag = {1};
  mesh.faceEdgeMask = {kAllEdges};
  for (std::size_t k = 0; k < times.size(); ++k) {
    MeshField step;
    step.name = "u";
    step.step = static_cast<int>(k);
    step.time = times[k];
    step.values = {0, 1, static_cast<float>(k)};
    mesh.fields.push_back(step);
  }
  return mesh;
}

SceneDescription colouredBy(const std::string& field) {
  SceneDescription description;
  MeshInstance mesh;
  ColorBy color;
  color.field = field;
  mesh.colorBy = color;
  description.meshes.push_back(mesh);
  return description;
}

TEST(StepTimes, RepeatedTimesGiveOneFramePerStepLabelledWithItsOwnTime) {
  const std::vector<Mesh> meshes{triangleWithTimes({0, 0, 0.0025, 0.005})};
  AnimationSettings animation;
  animation.overSteps = true;
  StepFrames frames = planStepFrames(colouredBy("u"), meshes, animation);
  EXPECT_EQ(frames.times, (std::vector<double>{0, 1, 2, 3}));  // by step index
  EXPECT_EQ(frames.labelTimes, (std::vector<double>{0, 0, 0.0025, 0.005}));
  EXPECT_TRUE(frames.note.empty());
  EXPECT_EQ(formatStepLabel("t = {time:.3g} s", frames.labelTimes[2], frames.steps[2], {}), "t = 0.0025 s");
  // Interpolated frames need increasing times: they fall on the steps instead, with a note.
  animation.frames = 20;
  animation.framesGiven = true;
  frames = planStepFrames(colouredBy("u"), meshes, animation);
  EXPECT_EQ(frames.times.size(), 4u);
  EXPECT_EQ(frames.labelTimes.back(), 0.005);
  EXPECT_NE(frames.note.find("the times of view \"u\" do not increase with its steps"), std::string::npos)
      << frames.note;
  EXPECT_NE(frames.note.find("4 frames, one per step, instead of 20"), std::string::npos) << frames.note;
}

TEST(StepTimes, UnsortedTimesKeepTheirOwn) {
  // Eigenmodes: frequencies in the order the solver found them.
  const std::vector<Mesh> meshes{triangleWithTimes({12.5, 3.1, 40.2})};
  AnimationSettings animation;
  animation.overSteps = true;
  const StepFrames frames = planStepFrames(colouredBy("u"), meshes, animation);
  EXPECT_EQ(frames.labelTimes, (std::vector<double>{12.5, 3.1, 40.2}));
}

TEST(StepTimes, IncreasingTimesAreTheTimeline) {
  const std::vector<Mesh> meshes{triangleWithTimes({0, 0.5, 2})};
  AnimationSettings animation;
  animation.overSteps = true;
  animation.frames = 5;
  animation.framesGiven = true;
  const StepFrames frames = planStepFrames(colouredBy("u"), meshes, animation);
  EXPECT_EQ(frames.times, (std::vector<double>{0, 0.5, 1, 1.5, 2}));
  EXPECT_EQ(frames.labelTimes, frames.times);  // a frame between steps shows its own time
  EXPECT_TRUE(frames.note.empty());
}

}  // namespace
}  // namespace lancer
