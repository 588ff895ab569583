// Bad results input: each error names the file, the view and the step, and says what to do; the CLI
// exits with 2.
#include <gtest/gtest.h>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/color_by.hpp"
#include "lancer/scene/results/result_keys.hpp"
#include "lancer/scene/results/step_files.hpp"
#include "lancer/scene/results/warp.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

Mesh cantilever() { return readMsh(test::dataFile("results/cantilever.msh")); }

std::string warpError(const std::string& field, StepSelection when = {}) {
  Mesh mesh = cantilever();
  const Mesh fields = cantilever();
  WarpSettings warp;
  warp.field = field;
  warp.where = SourceLocation{"scene.toml", 4, 8};
  return test::messageOf([&] { warpMesh(mesh, fields, warp, when); });
}

TEST(ResultsBadInput, WarpByAViewThatIsNotANodeVector) {
  const std::string file = test::dataFile("results/cantilever.msh");
  EXPECT_EQ(warpError("stress"),
            "scene.toml:4:8: error: warp field \"stress\" in " + file +
                " has 9 components per node: a warp needs a vector of 3 (a displacement); "
                "colour by this view instead");
  EXPECT_NE(warpError("temperature").find("is element data ($ElementData), one value per element"),
            std::string::npos);
  EXPECT_NE(warpError("displacment").find("is not in " + file + " (did you mean 'displacement'?); it has"),
            std::string::npos)
      << warpError("displacment");
}

TEST(ResultsBadInput, StepPastTheLast) {
  EXPECT_NE(
      warpError("displacement", StepSelection{7, {}, "--step"})
          .find(
              "warp field \"displacement\" has no step 7: its steps are 0, 1, 2, 3 (give a step from 0 to 3) "
              "in " +
              test::dataFile("results/cantilever.msh") + " (--step)"),
      std::string::npos)
      << warpError("displacement", StepSelection{7, {}, "--step"});
  ColorBy spec;
  spec.field = "temperature";
  spec.where = SourceLocation{"scene.toml", 6, 12};
  const std::string message = test::messageOf([&] {
    resolveColorBy(spec, cantilever(), StepSelection{4, {}, "--step"});
  });
  EXPECT_NE(message.find("color_by field \"temperature\" has no step 4"), std::string::npos) << message;
  EXPECT_NE(message.find("(--step)"), std::string::npos) << message;
}

TEST(ResultsBadInput, WarpFieldWithoutValuesForSomeNodes) {
  Mesh mesh = cantilever();
  MeshField partial{"d", FieldAt::kNode, 3, 0, 0.0, std::vector<float>(3 * mesh.positions.size(), 0.0f)};
  for (int i = 0; i < 6; ++i) partial.values[static_cast<std::size_t>(i)] = NAN;
  mesh.fields.push_back(partial);
  const Mesh fields = mesh;
  WarpSettings warp;
  warp.field = "d";
  warp.where = SourceLocation{"scene.toml", 2, 1};
  const std::string message = test::messageOf([&] { warpMesh(mesh, fields, warp, {}); });
  EXPECT_NE(message.find("warp field \"d\" step 0 in " + test::dataFile("results/cantilever.msh") +
                         " gives no vector for 2 of the mesh's"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("a warp needs one for every node"), std::string::npos);
}

// A view the reader skipped (here for a NaN) is named with the reader's reason, not as missing.
TEST(ResultsBadInput, WarpByAViewTheReaderSkipped) {
  const test::ScratchFolder folder;
  folder.write("nan.msh",
               "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
               "$EndNodes\n$Elements\n2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n$EndElements\n"
               "$NodeData\n1\n\"u\"\n1\n0\n3\n0\n3\n4\n1 0 0 nan\n2 0 0 0\n3 0 0 0\n4 0 0 0\n"
               "$EndNodeData\n");
  Mesh mesh = readMsh(folder.file("nan.msh"));
  const Mesh fields = mesh;
  WarpSettings warp;
  warp.field = "u";
  warp.where = SourceLocation{"scene.toml", 2, 1};
  const std::string message = test::messageOf([&] { warpMesh(mesh, fields, warp, {}); });
  EXPECT_NE(message.find("warp field \"u\": its section in " + folder.file("nan.msh") +
                         " could not be read and was skipped ("),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
}

TEST(ResultsBadInput, ComponentThatDoesNotExist) {
  ColorBy spec;
  spec.field = "displacement";
  spec.where = SourceLocation{"scene.toml", 6, 12};
  spec.component = FieldComponent{FieldComponent::Kind::VonMises, 0};
  EXPECT_EQ(test::messageOf([&] { resolveColorBy(spec, cantilever()); }),
            "scene.toml:6:12: error: color_by field \"displacement\" in " +
                test::dataFile("results/cantilever.msh") +
                ": von_mises needs a tensor of 9 components, the view is a vector (3 components); use "
                "\"magnitude\" "
                "or 0 to 2");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"s\", component = \"w\" }\n",
      "mesh[0].color_by.component must be \"magnitude\", \"x\", \"y\", \"z\", \"von_mises\" "
      "or an index 0 to 8, found string \"w\"");
}

TEST(ResultsBadInput, LabelWithAnUnknownName) {
  test::expectSceneErrorContains(
      "[animation]\nover = \"steps\"\nlabel = \"t = {t:.3g}\"\n",
      "the label \"t = {t:.3g}\" cannot be formatted (argument not found): it may use "
      "{time} and {step}");
  EXPECT_EQ(formatStepLabel("t = {time:.3g} s, step {step}", 0.123456, 4, SourceLocation{}),
            "t = 0.123 s, step 4");
}

TEST(ResultsBadInput, LabelWidthsAndLengthsAreBoundedBeforeFormatting) {
  // "{time:1500000000}" formatted a string of 1.5 GB.
  EXPECT_EQ(test::messageOf([] { formatStepLabel("{time:1500000000}", 0.5, 1, SourceLocation{"--label"}); }),
            "--label: error: the label \"{time:1500000000}\" asks for a width or precision of 1500000000; at "
            "most 64 are allowed");
  EXPECT_NE(test::messageOf([] {
              formatStepLabel("t = {time:.99999999999999999999g}", 0, 1, {});
            }).find("a width or precision of 99999999999999999999;"),
            std::string::npos);
  EXPECT_NE(test::messageOf([] {
              formatStepLabel("{time:{step}}", 0, 1, {});
            }).find("takes a width or precision from another field"),
            std::string::npos);
  EXPECT_EQ(test::messageOf([] { formatStepLabel(std::string(201, 'x'), 0, 1, SourceLocation{"--label"}); }),
            "--label: error: the label is 201 characters long; at most 200 are drawn");
  EXPECT_EQ(formatStepLabel("{{time:1500000000}} {time:>12.3e}", 0.5, 1, {}),
            "{time:1500000000}    5.000e-01");
  EXPECT_EQ(formatStepLabel(std::string(100, 'x') + "\u00e9", 0, 1, {}).size(), 102u);  // 101 characters
  test::expectSceneErrorContains(
      "[animation]\nover = \"steps\"\nlabel = \"" + std::string(300, 'x') + "\"\n",
      "scene.toml:3:9: error: animation.label is 300 characters long; at most 200 are drawn");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\ncolor_by = { field = \"s\", title = \"" +
                                     std::string(24000, 'T') + "\" }\n",
                                 "mesh[0].color_by.title is 24000 characters long; at most 200 are drawn");
}

TEST(ResultsBadInput, SceneKeys) {
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\nwarp = \"displacement\"\n",
      "mesh[0].warp must be a table like { field = \"displacement\", factor = 2.0 }");
  test::expectSceneErrorContains("[[mesh]]\nfile = \"a.msh\"\nwarp = { factor = 2 }\n",
                                 "field = \"displacement\"");
  test::expectSceneErrorContains(
      "[[mesh]]\nfile = \"a.msh\"\nundeformed = \"edges\"\n",
      "mesh[0].undeformed shows the shape before a warp, but this mesh has no warp");
  test::expectSceneErrorContains("[animation]\nover = \"time\"\n", "animation.over");
}

TEST(ResultsBadInput, FilePatternMatchingNothing) {
  const std::string folder = test::dataFile("results/steps");
  const std::string message = test::messageOf([&] {
    matchStepFiles(folder + "/result_*.msh", SourceLocation{"scene.toml", 3, 8});
  });
  EXPECT_EQ(message, "scene.toml:3:8: error: no file matches 'result_*.msh' in '" + folder +
                         "' (its .msh files: step_1.msh, step_2.msh, step_10.msh); give a pattern such as "
                         "\"result_*.msh\" that names one file per step");
}

TEST(ResultsBadInput, FilesWhoseMeshesDiffer) {
  const test::ScratchFolder folder;
  folder.copy(test::dataFile("results/steps/step_1.msh"), "r_1.msh");
  folder.copy(test::dataFile("fields/node_vector_v41_bin.msh"), "r_2.msh");
  const std::string pattern = folder.file("r_*.msh");
  const std::string message = test::messageOf([&] {
    readStepFiles(pattern, matchStepFiles(pattern, SourceLocation{"scene.toml"}), 0,
                  SourceLocation{"scene.toml"});
  });
  EXPECT_NE(message.find(folder.file("r_2.msh") + " is step 1 of the pattern, but its mesh differs from " +
                         folder.file("r_1.msh") + "'s ("),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("steps in several files need one mesh"), std::string::npos);
}

TEST(ResultsBadInput, CommandLine) {
  const std::string mesh = test::quoted(test::dataFile("results/cantilever.msh"));
  const test::ScratchFolder folder;
  const std::string out = " -o " + test::quoted(folder.file("out.png")) + " --width 32 --height 24";
  test::CommandResult result = test::runCli("render " + mesh + " --warp stress:2" + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("--warp: error: warp field \"stress\""), std::string::npos) << result.output;
  result = test::runCli("render " + mesh + " --warp displacement --step 9" + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("has no step 9"), std::string::npos) << result.output;
  result = test::runCli("render " + mesh + " --color-by displacement:tangent" + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("'tangent' is not a component"), std::string::npos) << result.output;
  result = test::runCli("render " + mesh + " --warp displacement:big" + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("the factor 'big' is not a number"), std::string::npos) << result.output;
  result = test::runCli("render " + test::quoted(folder.file("none_*.msh")) + out);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.output.find("no file matches 'none_*.msh'"), std::string::npos) << result.output;
  result = test::runCli("animate " + mesh + " --over steps -o " + test::quoted(folder.file("a.gif")));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(
      result.output.find(
          "an animation over steps needs a mesh coloured (color_by), warped (warp), with isolines or arrows"),
      std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace lancer
