// The steps of gmsh views (tests/data/results/cantilever.msh, made by scripts/make_result_fixtures.py
// with gmsh's API): every step of every view kept, in time order; blends between steps; components.
#include "lancer/mesh/field_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/msh_reader.hpp"
#include "support/cantilever.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

constexpr double kLength = test::kCantileverLength;
using test::cantilever;

double deflection(double x, double t) { return test::cantileverDeflection(x, t); }

TEST(FieldSteps, EveryStepOfEveryViewIsKeptInTimeOrder) {
  const Mesh mesh = cantilever();
  EXPECT_EQ(viewNames(mesh), (std::vector<std::string>{"displacement", "stress", "temperature"}));
  for (const std::string& name : viewNames(mesh)) {
    const std::vector<const MeshField*> steps = viewSteps(mesh, name);
    ASSERT_EQ(steps.size(), 4u) << name;
    for (std::size_t k = 0; k < steps.size(); ++k) {
      EXPECT_EQ(steps[k]->step, static_cast<int>(k));
      EXPECT_DOUBLE_EQ(stepTime(steps, k), 0.5 * static_cast<double>(k));
    }
  }
  EXPECT_EQ(stepTimes(mesh, {"displacement", "temperature"}), (std::vector<double>{0, 0.5, 1, 1.5}));
  EXPECT_EQ(describeViews(mesh),
            "\"displacement\" (steps 0, 1, 2, 3), \"stress\" (steps 0, 1, 2, 3), \"temperature\" (steps 0, "
            "1, 2, 3)");
}

TEST(FieldSteps, AStepIsTheFileValuesAndATimeBetweenStepsBlendsLinearly) {
  const Mesh mesh = cantilever();
  const auto steps = viewSteps(mesh, "displacement");
  std::string problem;
  const std::optional<MeshField> step2 = viewAt(steps, StepSelection{2, std::nullopt, ""}, problem);
  ASSERT_TRUE(step2) << problem;
  const std::optional<MeshField> quarter = viewAt(steps, StepSelection{std::nullopt, 0.25, ""}, problem);
  ASSERT_TRUE(quarter) << problem;
  EXPECT_EQ(quarter->step, -1);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const double x = mesh.worldPosition(static_cast<std::uint32_t>(v)).x;
    EXPECT_NEAR(step2->values[3 * v + 1], -deflection(x, 1.0), 1e-6);
    EXPECT_NEAR(quarter->values[3 * v + 1], -deflection(x, 0.25), 1e-6);
  }
  // Before the first step and after the last: the end steps.
  EXPECT_EQ(viewAt(steps, StepSelection{std::nullopt, -3.0, ""}, problem)->values, steps.front()->values);
  EXPECT_EQ(viewAt(steps, StepSelection{std::nullopt, 99.0, ""}, problem)->values, steps.back()->values);
}

TEST(FieldSteps, AStepPastTheLastSaysWhichStepsThereAre) {
  const Mesh mesh = cantilever();
  std::string problem;
  EXPECT_FALSE(viewAt(viewSteps(mesh, "stress"), StepSelection{4, std::nullopt, ""}, problem));
  EXPECT_EQ(problem, "has no step 4: its steps are 0, 1, 2, 3 (give a step from 0 to 3)");
}

TEST(FieldSteps, ViewsTimedZeroAtEveryStepAreTimedByTheirStepIndex) {
  Mesh mesh;
  for (int k : {2, 0, 1}) mesh.fields.push_back(MeshField{"t", FieldAt::kNode, 1, k, 0.0, {float(k)}});
  const auto steps = viewSteps(mesh, "t");
  ASSERT_EQ(steps.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(steps[k]->step, static_cast<int>(k));
    EXPECT_EQ(stepTime(steps, k), static_cast<double>(k));
  }
}

TEST(FieldComponents, NamesAndIndices) {
  using Kind = FieldComponent::Kind;
  EXPECT_EQ(parseFieldComponent("magnitude"), (FieldComponent{Kind::Magnitude, 0}));
  EXPECT_EQ(parseFieldComponent("von_mises"), (FieldComponent{Kind::VonMises, 0}));
  EXPECT_EQ(parseFieldComponent("y"), (FieldComponent{Kind::Index, 1}));
  EXPECT_EQ(parseFieldComponent("8"), (FieldComponent{Kind::Index, 8}));
  EXPECT_FALSE(parseFieldComponent("9"));
  EXPECT_FALSE(parseFieldComponent("w"));
  EXPECT_FALSE(parseFieldComponent(""));
  EXPECT_EQ(
      componentProblem(FieldComponent{Kind::VonMises, 0}, 3),
      "von_mises needs a tensor of 9 components, the view is a vector (3 components); use \"magnitude\" or 0 "
      "to 2");
  EXPECT_EQ(componentProblem(FieldComponent{Kind::Index, 3}, 3),
            "component 3 does not exist: the view is a vector (3 components); use \"magnitude\" or 0 to 2");
  EXPECT_EQ(componentProblem(FieldComponent{Kind::Index, 2}, 3), "");
}

TEST(FieldComponents, VonMisesOfUniaxialStressAndPureShear) {
  const FieldComponent vonMises{FieldComponent::Kind::VonMises, 0};
  const float uniaxial[9] = {-3, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_FLOAT_EQ(componentScalar(uniaxial, 9, vonMises), 3);
  const float shear[9] = {0, 2, 0, 2, 0, 0, 0, 0, 0};  // sqrt(3) tau
  EXPECT_FLOAT_EQ(componentScalar(shear, 9, vonMises), 2 * std::sqrt(3.0f));
  const float hydrostatic[9] = {5, 0, 0, 0, 5, 0, 0, 0, 5};
  EXPECT_FLOAT_EQ(componentScalar(hydrostatic, 9, vonMises), 0);
  const float vector[3] = {3, -4, 0};
  EXPECT_FLOAT_EQ(componentScalar(vector, 3, FieldComponent{}), 5);
  EXPECT_FLOAT_EQ(componentScalar(vector, 3, FieldComponent{FieldComponent::Kind::Index, 1}), -4);
}

}  // namespace
}  // namespace lancer
