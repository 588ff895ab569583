// Results over time on the gmsh-made cantilever (tests/data/results/, scripts/make_result_fixtures.py):
// the warp moves each node by the closed-form displacement, colours keep one range over every step,
// faces a warp collapses are dropped and counted, steps from several files in natural order.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/step_files.hpp"
#include "lancer/scene/results/warp.hpp"
#include "lancer/scene/scene.hpp"
#include "support/cantilever.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

constexpr double kLength = test::kCantileverLength;
using test::cantilever;

double deflection(double x, double t) { return test::cantileverDeflection(x, t); }

WarpSettings warpBy(const std::string& field, double factor) {
  WarpSettings warp;
  warp.field = field;
  warp.factor = factor;
  warp.where = SourceLocation{"scene.toml", 3, 1};
  return warp;
}

TEST(Warp, MovesEveryNodeByFactorTimesItsDisplacementAtTheStep) {
  const Mesh original = cantilever();
  for (const int step : {0, 3}) {
    Mesh mesh = cantilever();
    const WarpReport report =
        warpMesh(mesh, original, warpBy("displacement", 2.0), StepSelection{step, {}, ""});
    EXPECT_EQ(report.collapsedFaces, 0u);
    ASSERT_EQ(mesh.positions.size(), original.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const Vec3d before = original.worldPosition(static_cast<std::uint32_t>(v));
      const Vec3d after = mesh.worldPosition(static_cast<std::uint32_t>(v));
      EXPECT_NEAR(after.x, before.x, 1e-5);
      EXPECT_NEAR(after.y, before.y - 2.0 * deflection(before.x, 0.5 * step), 1e-5);
      EXPECT_NEAR(after.z, before.z, 1e-5);
    }
  }
}

TEST(Warp, CollapsedFacesAreDroppedAndCountedWithoutNaN) {
  // The half x > 5 squashed onto the plane x = 5: its faces along the beam collapse; the end cap
  // moves onto the plane and keeps its area.
  Mesh mesh = cantilever();
  MeshField squash{"squash", FieldAt::kNode, 3, 0, 0.0, {}};
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const double x = mesh.worldPosition(static_cast<std::uint32_t>(v)).x;
    squash.values.insert(squash.values.end(), {x > 5 ? static_cast<float>(5 - x) : 0.0f, 0, 0});
  }
  mesh.fields.push_back(squash);
  SceneDescription description;
  description.materials.push_back(Material{});
  MeshInstance instance;
  instance.file = "cantilever.msh";
  instance.warp = warpBy("squash", 1.0);
  description.meshes.push_back(instance);
  const std::size_t faces = mesh.faces.size();
  const Scene scene = buildScene(description, {mesh});
  const std::size_t kept = scene.geometry.faces.size();
  EXPECT_LT(kept, faces * 3 / 4);
  EXPECT_GT(kept, faces / 3);
  for (const Vec3& p : scene.geometry.positions) EXPECT_TRUE(isFinite(p));
  for (const Vec3& n : scene.geometry.faceNormals) EXPECT_NEAR(length(n), 1.0f, 1e-4f);
  ASSERT_FALSE(scene.warnings.empty());
  EXPECT_NE(scene.warnings.back().find(fmt::format("{} of", faces - kept)), std::string::npos)
      << scene.warnings.back();
  EXPECT_NE(scene.warnings.back().find("collapsed under the warp (factor 1) and were dropped"),
            std::string::npos);
}

TEST(ColorRange, OverEveryStepByDefaultOrPerStep) {
  const Mesh mesh = cantilever();
  ColorBy spec;
  spec.field = "temperature";  // 10 t + (tag mod 3): step k spans [5k, 5k + 2]
  const FieldColoring all = resolveColorBy(spec, mesh, StepSelection{1, {}, ""});
  EXPECT_EQ(all.low, 0);
  EXPECT_EQ(all.high, 17);
  spec.perStepRange = true;
  const FieldColoring own = resolveColorBy(spec, mesh, StepSelection{1, {}, ""});
  EXPECT_EQ(own.low, 5);
  EXPECT_EQ(own.high, 7);
  spec.perStepRange = false;
  spec.field = "stress";  // sigma_xx = t (L - x)(y - 1/2): von Mises up to 1.5 * 10 * 0.5
  spec.component = FieldComponent{FieldComponent::Kind::VonMises, 0};
  const FieldColoring stress = resolveColorBy(spec, mesh, StepSelection{2, {}, ""});
  EXPECT_NEAR(stress.low, 0, 1e-6);
  EXPECT_NEAR(stress.high, 7.5, 1e-5);
}

TEST(StepFiles, NaturalOrder) {
  EXPECT_TRUE(naturalLess("step_2.msh", "step_10.msh"));
  EXPECT_FALSE(naturalLess("step_10.msh", "step_2.msh"));
  EXPECT_TRUE(naturalLess("a_01.msh", "a_2.msh"));
  EXPECT_TRUE(naturalLess("a.msh", "b.msh"));
  EXPECT_FALSE(naturalLess("a.msh", "a.msh"));
}

TEST(StepFiles, EachFileIsAStepInNaturalOrderOnOneMesh) {
  const std::string pattern = test::dataFile("results/steps/step_*.msh");
  const std::vector<std::string> files = matchStepFiles(pattern, SourceLocation{"scene.toml"});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_TRUE(files[2].ends_with("step_10.msh")) << files[2];
  const Mesh mesh = readStepFiles(pattern, files, 0, SourceLocation{"scene.toml"});
  const auto steps = viewSteps(mesh, "displacement");
  ASSERT_EQ(steps.size(), 3u);
  const double tips[] = {0.1, 0.2, 1.0};  // the files' times: the tip deflection
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(steps[k]->step, static_cast<int>(k));
    EXPECT_NEAR(stepTime(steps, k), tips[k], 1e-12);
    float lowest = 0;
    for (std::size_t i = 1; i < steps[k]->values.size(); i += 3)
      lowest = std::min(lowest, steps[k]->values[i]);
    EXPECT_NEAR(lowest, -tips[k], 1e-6);
  }
  EXPECT_NE(mesh.source.path.find("step_*.msh (3 files)"), std::string::npos) << mesh.source.path;
}

// Files that hold several steps each: the steps follow each other over the files (0 to 3 for two
// files of two), each with the time its file gives it.
TEST(StepFiles, FilesOfSeveralStepsAreNumberedOneAfterTheOther) {
  const test::ScratchFolder folder;
  const auto square = [](double firstTime) {
    std::string text =
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
        "$EndNodes\n$Elements\n2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n$EndElements\n";
    for (int step = 0; step < 2; ++step)
      text += fmt::format("$NodeData\n1\n\"f\"\n1\n{}\n3\n{}\n1\n4\n1 {}\n2 {}\n3 {}\n4 {}\n$EndNodeData\n",
                          firstTime + step, 5 + step, firstTime + step, firstTime + step, firstTime + step,
                          firstTime + step);
    return text;
  };
  folder.write("run_1.msh", square(0));
  folder.write("run_2.msh", square(2));
  const std::string pattern = folder.file("run_*.msh");
  const std::vector<std::string> files = matchStepFiles(pattern, SourceLocation{"scene.toml"});
  const Mesh mesh = readStepFiles(pattern, files, 0, SourceLocation{"scene.toml"});
  const auto steps = viewSteps(mesh, "f");
  ASSERT_EQ(steps.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(steps[k]->step, static_cast<int>(k));
    EXPECT_DOUBLE_EQ(steps[k]->time, static_cast<double>(k));
    EXPECT_FLOAT_EQ(steps[k]->values.front(), static_cast<float>(k));
  }
}

}  // namespace
}  // namespace lancer
