// Arrows and isolines follow the step or time the scene shows (an animation over steps sets it per
// frame), as colours and warps do: arrows of a field that turns between two steps turn with it and
// blend between them; their automatic scale and the isolines' values stay fixed over the steps; a
// pinned step keeps them still. The cantilever's displacement is known in closed form
// (scripts/make_result_fixtures.py): w(x, t) = t x^2 (3 L - x) / (2 L^3), the tip moving down by t.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lancer/image/legend.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/render/step_animation.hpp"
#include "lancer/scene/results/arrows.hpp"
#include "lancer/scene/results/isolines.hpp"
#include "lancer/scene/scene.hpp"
#include "support/files.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// A 4 x 4 grid of quads over the unit square (z = 0) whose "velocity" points along +x at step 0
// (time 0) and along +y, twice as long, at step 1 (time 1).
Mesh turningFlow() {
  Mesh mesh;
  constexpr int kSide = 4;
  for (int j = 0; j <= kSide; ++j)
    for (int i = 0; i <= kSide; ++i) mesh.positions.push_back({float(i) / kSide, float(j) / kSide, 0});
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const auto v = static_cast<std::uint32_t>(j * (kSide + 1) + i);
      mesh.faces.push_back(MeshFace{{v, v + 1, v + 2 + kSide, v + 1 + kSide}});
    }
  mesh.facePhysicalTag.assign(mesh.faces.size(), 0);
  mesh.faceEntityTag.assign(mesh.faces.size(), 1);
  mesh.faceEdgeMask.assign(mesh.faces.size(), kAllEdges);
  for (int step = 0; step < 2; ++step) {
    MeshField field;
    field.name = "velocity";
    field.components = 3;
    field.step = step;
    field.time = step;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      field.values.insert(field.values.end(), {step == 0 ? 1.0f : 0.0f, step == 0 ? 0.0f : 2.0f, 0.0f});
    mesh.fields.push_back(field);
  }
  mesh.source.path = "turning_flow";
  return mesh;
}

// Each arrow's base-to-tip vector (an arrow's last two vertices are its base centre and its tip).
std::vector<Vec3> arrowVectors(const Mesh& arrows) {
  const std::size_t perArrow = 3 * kArrowSides + 2;
  std::vector<Vec3> vectors;
  for (std::size_t first = 0; first + perArrow <= arrows.positions.size(); first += perArrow)
    vectors.push_back(arrows.positions[first + perArrow - 1] - arrows.positions[first + perArrow - 2]);
  return vectors;
}

StepSelection atStep(int step) { return StepSelection{step, std::nullopt, "test"}; }
StepSelection atTime(double time) { return StepSelection{std::nullopt, time, "test"}; }

TEST(AnnotationsOverSteps, ArrowsTurnWithTheirFieldAndKeepOneScale) {
  const Mesh mesh = turningFlow();
  ArrowSpec spec;
  spec.field = "velocity";
  spec.maxCount = 9;
  const std::vector<Vec3> first = arrowVectors(arrowMesh(spec, mesh, atStep(0)));
  const std::vector<Vec3> second = arrowVectors(arrowMesh(spec, mesh, atStep(1)));
  const std::vector<Vec3> between = arrowVectors(arrowMesh(spec, mesh, atTime(0.5)));
  ASSERT_FALSE(first.empty());
  ASSERT_EQ(first.size(), second.size());
  ASSERT_EQ(first.size(), between.size());
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_NEAR(first[k].y, 0, 1e-5);  // along +x
    EXPECT_GT(first[k].x, 0);
    EXPECT_NEAR(second[k].x, 0, 1e-5);  // along +y
    EXPECT_GT(second[k].y, 0);
    // One scale over both steps: the step-1 vectors are twice as long, so their arrows too.
    EXPECT_NEAR(length(second[k]), 2 * length(first[k]), 1e-4);
    // Half-way in time: the blend (0.5, 1, 0), as long as its magnitude says.
    EXPECT_NEAR(between[k].y / between[k].x, 2, 1e-3);
    EXPECT_NEAR(length(between[k]), std::sqrt(1.25) * length(first[k]), 1e-4);
  }
  // A pinned step keeps its arrows whatever the scene shows; its own longest arrow sets the scale.
  spec.step = 0;
  const std::vector<Vec3> pinned = arrowVectors(arrowMesh(spec, mesh, atStep(1)));
  ASSERT_EQ(pinned.size(), first.size());
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_NEAR(pinned[k].y, 0, 1e-5);
    EXPECT_NEAR(length(pinned[k]), 2 * length(first[k]), 1e-4);
  }
}

TEST(AnnotationsOverSteps, TheScenesArrowsAreThoseOfItsStep) {
  SceneDescription description;
  description.materials.push_back(Material{});
  MeshInstance instance;
  instance.file = "turning_flow";
  ArrowSpec spec;
  spec.field = "velocity";
  spec.maxCount = 9;
  instance.annotations.push_back(spec);
  description.meshes.push_back(instance);
  std::vector<Mesh> meshes{turningFlow()};
  description.when = atStep(0);
  const Scene first = buildSceneAt(description, meshes, 1);
  description.when = atStep(1);
  const Scene second = buildSceneAt(description, meshes, 1);
  // The arrows' vertices follow the grid's 25 in the scene: along x at step 0, along y at step 1.
  auto sceneArrows = [&](const Scene& scene) {
    Mesh arrows;
    arrows.positions.assign(scene.geometry.positions.begin() + 25, scene.geometry.positions.end());
    return arrowVectors(arrows);
  };
  const std::vector<Vec3> a = sceneArrows(first), b = sceneArrows(second);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_GT(a[k].x, 0);
    EXPECT_NEAR(a[k].y, 0, 1e-5);
    EXPECT_NEAR(b[k].x, 0, 1e-5);
    EXPECT_GT(b[k].y, 0);
  }
  ASSERT_TRUE(first.fieldColors && second.fieldColors);
  // The arrows' colours span one range over the steps: their magnitudes 1 and 2.
  ASSERT_FALSE(first.fieldColors->legends.empty());
  EXPECT_EQ(first.fieldColors->legends.front().low, 1);
  EXPECT_EQ(first.fieldColors->legends.front().high, 2);
  EXPECT_EQ(second.fieldColors->legends.front().low, 1);
}

TEST(AnnotationsOverSteps, ArrowsAloneMakeAnAnimationOverSteps) {
  SceneDescription description;
  MeshInstance instance;
  ArrowSpec spec;
  spec.field = "velocity";
  instance.annotations.push_back(spec);
  description.meshes.push_back(instance);
  std::vector<Mesh> meshes{turningFlow()};
  EXPECT_EQ(planStepFrames(description, meshes, AnimationSettings{}).times, (std::vector<double>{0, 1}));
  std::get<ArrowSpec>(description.meshes[0].annotations[0]).step = 0;  // pinned: no steps to run through
  EXPECT_THROW(planStepFrames(description, meshes, AnimationSettings{}), InputError);
}

TEST(AnnotationsOverSteps, IsolinesFollowTheStepWithValuesFixedOverTheSteps) {
  // The displacement's y component -w(x, t) at steps 1 (t = 0.5) and 3 (t = 1.5): three times as
  // large at step 3 at every node, on lines at the same values (spread over every step's range).
  const Mesh mesh = readMsh(test::dataFile("results/cantilever.msh"));
  IsolineSpec spec;
  spec.field = "displacement";
  spec.component = FieldComponent{FieldComponent::Kind::Index, 1};
  spec.count = 5;
  const ResolvedIsolines early = resolveIsolines(spec, mesh, atStep(1));
  const ResolvedIsolines late = resolveIsolines(spec, mesh, atStep(3));
  EXPECT_EQ(early.values, late.values);
  ASSERT_EQ(late.values.size(), 5u);
  EXPECT_NEAR(late.values.front(), -1.5 + 0.15, 1e-5);  // (-1.5 .. 0) in 5 intervals, the middles
  ASSERT_EQ(early.vertexValue.size(), late.vertexValue.size());
  for (std::size_t v = 0; v < early.vertexValue.size(); ++v) {
    const double x = mesh.worldPosition(static_cast<std::uint32_t>(v)).x;
    const double w = x * x * (3 * 10 - x) / (2 * 1000.0);
    EXPECT_NEAR(early.vertexValue[v], -0.5 * w, 1e-5);
    EXPECT_NEAR(late.vertexValue[v], -1.5 * w, 1e-5);
  }
  // Half-way between steps 1 and 2 in time (t = 0.75): the blend.
  const ResolvedIsolines between = resolveIsolines(spec, mesh, atTime(0.75));
  for (std::size_t v = 0; v < between.vertexValue.size(); ++v)
    EXPECT_NEAR(between.vertexValue[v], 1.5 * early.vertexValue[v], 1e-5);
  // Pinned to step 1: its own values, whatever the scene shows, spread over that step's range.
  spec.step = 1;
  const ResolvedIsolines pinned = resolveIsolines(spec, mesh, atStep(3));
  EXPECT_EQ(pinned.vertexValue, early.vertexValue);
  EXPECT_NEAR(pinned.values.front(), -0.5 + 0.05, 1e-5);
}

TEST(AnnotationsOverSteps, EachFramesLegendShowsTheRangeOfItsColours) {
  // The turning flow's speed is 1 everywhere at step 0 and 2 at step 1. With range = "step" each
  // frame's colours span its own step (one value: the map's middle colour in both frames), so only
  // the legend's label tells the frames apart; with the default range both frames share [1, 2].
  std::vector<Mesh> meshes{turningFlow()};
  const auto frames = [&](bool perStepRange, LegendPlacement legend) {
    SceneDescription description =
        test::flatLitOnBlue(test::orthographicView(96, 64, {0.5, 0.5, 5}, {0.5, 0.5, 0}, 1.5), {0.5, 0.5, 5});
    description.materials = {test::matteMaterial("plain", {0.2f, 0.2f, 0.2f}, {0.7f, 0.7f, 0.7f})};
    MeshInstance instance;
    ColorBy colour;
    colour.field = "velocity";
    colour.perStepRange = perStepRange;
    colour.legend = legend;
    instance.colorBy = colour;
    description.meshes.push_back(instance);
    StepScenes steps(description, meshes, AnimationSettings{}, kDefaultAccel, 1);
    std::vector<Image> images;
    std::vector<std::pair<double, double>> ranges;
    for (int frame = 0; frame < steps.frameCount(); ++frame) {
      images.push_back(steps.render(frame, RenderOptions{}));
      const LegendSpec& shown = steps.frameScene()->fieldColors->legends.at(0);
      ranges.emplace_back(shown.low, shown.high);
    }
    return std::pair{images, ranges};
  };
  const auto [perStep, perStepRanges] = frames(true, LegendPlacement::Right);
  ASSERT_EQ(perStep.size(), 2u);
  EXPECT_EQ(perStepRanges, (std::vector<std::pair<double, double>>{{1, 1}, {2, 2}}));
  EXPECT_NE(perStep[0], perStep[1]);  // the labels 1 and 2
  const auto [unlabelled, ignored] = frames(true, LegendPlacement::None);
  EXPECT_EQ(unlabelled[0], unlabelled[1]);  // so the difference above is the legend's
  const auto [fixed, fixedRanges] = frames(false, LegendPlacement::Right);
  EXPECT_EQ(fixedRanges, (std::vector<std::pair<double, double>>{{1, 2}, {1, 2}}));
}

}  // namespace
}  // namespace lancer
