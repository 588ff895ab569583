// The list-based .pos reader on views gmsh and GetDP wrote (tests/data/pos/, from
// scripts/make_pos_fixtures.py): every element code, second order, time steps with their TIME list,
// several views per file, comments and the solvers' number formats. The gmsh fixtures' values are a
// closed form of their node's coordinates, so every value is checked against the coordinates read
// with it: node order, step order and component order all at once.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "lancer/mesh/pos/pos_reader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

std::string posFixture(const std::string& name) { return test::dataFile("pos/" + name); }

PosFile readText(const std::string& text, const std::string& name = "f.pos") {
  return readPosFromMemory(std::span<const char>(text.data(), text.size()), name);
}

// scripts/make_pos_fixtures.py's value(x, y, z, step, component).
double closedForm(const double* p, int step, int component) {
  return p[0] + 2 * p[1] + 4 * p[2] + 16 * step + component / 8.0;
}

// Every value of every element of `view` is closedForm of its node.
void expectClosedFormValues(const PosView& view) {
  for (const PosElementBlock& block : view.blocks) {
    SCOPED_TRACE(view.name + " " + block.kind.code());
    ASSERT_EQ(block.coords.size(), block.elementCount() * 3 * block.nodesPerElement());
    ASSERT_EQ(block.values.size(),
              block.elementCount() * view.stepCount * block.nodesPerElement() * block.components());
    for (std::size_t e = 0; e < block.elementCount(); ++e)
      for (int step = 0; step < view.stepCount; ++step) {
        const float* values = view.elementValues(block, e, step);
        for (int node = 0; node < block.nodesPerElement(); ++node) {
          const double* p = &block.coords[(e * block.nodesPerElement() + node) * 3];
          for (int c = 0; c < block.components(); ++c)
            ASSERT_EQ(values[node * block.components() + c], static_cast<float>(closedForm(p, step, c)))
                << "element " << e << " step " << step << " node " << node << " component " << c;
        }
      }
  }
}

TEST(PosReader, GmshListsOfEveryShapeInScalarVectorAndTensor) {
  const PosFile file = readPosFile(posFixture("gmsh_lists.pos"));
  ASSERT_EQ(file.views.size(), 3u);
  const char* names[] = {"scalar", "vector", "tensor"};
  const int components[] = {1, 3, 9};
  const char* codes[] = {"P", "L", "T", "Q", "S", "H", "I", "Y"};
  const int gmshTypes[] = {15, 1, 2, 3, 4, 5, 6, 7};
  const int nodes[] = {1, 2, 3, 4, 4, 8, 6, 5};
  for (int v = 0; v < 3; ++v) {
    const PosView& view = file.views[v];
    EXPECT_EQ(view.name, names[v]);
    EXPECT_EQ(view.stepCount, 2);
    EXPECT_TRUE(view.timesGiven);
    EXPECT_EQ(view.times, (std::vector<double>{0, 1}));
    EXPECT_EQ(view.components(), components[v]);
    EXPECT_EQ(view.elementCount(), 16u);
    ASSERT_EQ(view.blocks.size(), 8u);
    for (int shape = 0; shape < 8; ++shape) {
      const PosElementBlock& block = view.blocks[shape];
      EXPECT_EQ(block.kind.code(), std::string(1, "SVT"[v]) + codes[shape]);
      EXPECT_EQ(block.kind.gmshType, gmshTypes[shape]);
      EXPECT_EQ(block.nodesPerElement(), nodes[shape]);
      EXPECT_EQ(block.components(), components[v]);
      EXPECT_EQ(block.kind.order, 1);
      EXPECT_EQ(block.elementCount(), 2u);
    }
    expectClosedFormValues(view);
  }
  EXPECT_EQ(file.views[0].line, 1);
  EXPECT_EQ(file.views[0].blocks[0].lines, (std::vector<std::int64_t>{3, 4}));
  EXPECT_EQ(file.views[1].line, 22);
  // The 2D and 3D labels of "scalar" are skipped, with one warning.
  EXPECT_EQ(file.views[0].skippedTexts, 2u);
  EXPECT_EQ(file.views[1].skippedTexts, 0u);
  ASSERT_EQ(file.warnings.size(), 1u);
  EXPECT_EQ(file.warnings[0], file.file +
                                  ":19:1: warning: skipped 2 text annotations (T2, T3) of view \"scalar\": "
                                  "lancer draws no text from a .pos file");
}

TEST(PosReader, SecondOrderListsCarryEveryNodeOfTheirElement) {
  const PosFile file = readPosFile(posFixture("second_order.pos"));
  ASSERT_EQ(file.views.size(), 3u);
  const char* codes[] = {"L2", "T2", "Q2", "S2", "H2", "I2", "Y2"};
  const int gmshTypes[] = {8, 9, 10, 11, 12, 13, 14};
  const int nodes[] = {3, 6, 9, 10, 27, 18, 14};
  for (int v = 0; v < 3; ++v) {
    const PosView& view = file.views[v];
    EXPECT_EQ(view.times, (std::vector<double>{0.5, 1.5}));
    EXPECT_EQ(view.stepCount, 2);
    ASSERT_EQ(view.blocks.size(), 7u);
    for (int i = 0; i < 7; ++i) {
      EXPECT_EQ(view.blocks[i].kind.code(), std::string(1, "SVT"[v]) + codes[i]);
      EXPECT_EQ(view.blocks[i].kind.gmshType, gmshTypes[i]);
      EXPECT_EQ(view.blocks[i].kind.order, 2);
      EXPECT_EQ(view.blocks[i].nodesPerElement(), nodes[i]);
      EXPECT_EQ(view.blocks[i].elementCount(), 1u);
    }
    expectClosedFormValues(view);
  }
  EXPECT_EQ(file.views[2].name, "tensor2");
  EXPECT_EQ(file.views[2].blocks[4].kind.description(), "tensor 27-node hexahedron");
}

// The numbers of the first `count` numbers after `marker` in `text`, as strtod reads them.
std::vector<double> numbersAfter(const std::string& text, const std::string& marker, int count) {
  std::vector<double> numbers;
  const char* p = text.c_str() + text.find(marker) + marker.size();
  for (int i = 0; i < count; ++i) {
    char* end = nullptr;
    numbers.push_back(std::strtod(p, &end));
    p = end + 1;  // the ',', ')' or '{' after it
    if (*p == '{') ++p;
  }
  return numbers;
}

TEST(PosReader, GetDPMagnetDemo) {
  const std::string path = posFixture("magnet/az.pos");
  const PosFile az = readPosFile(path);
  ASSERT_EQ(az.views.size(), 1u);
  const PosView& view = az.views[0];
  EXPECT_EQ(view.name, "az");
  EXPECT_EQ(view.stepCount, 1);
  EXPECT_FALSE(view.timesGiven);
  EXPECT_EQ(view.times, (std::vector<double>{0}));
  ASSERT_EQ(view.blocks.size(), 1u);
  const PosElementBlock& block = view.blocks[0];
  EXPECT_EQ(block.kind.code(), "ST");
  EXPECT_EQ(block.kind.gmshType, 2);
  // One element a line, from line 2.
  const std::string text = test::readText(path);
  std::size_t lines = 0;
  for (std::size_t at = text.find("\nST("); at != std::string::npos; at = text.find("\nST(", at + 1)) ++lines;
  EXPECT_EQ(block.elementCount(), lines);
  EXPECT_GT(lines, 200u);
  EXPECT_EQ(block.lines.front(), 2);
  EXPECT_EQ(block.lines.back(), static_cast<std::int64_t>(lines + 1));
  // The first element, number for number.
  const std::vector<double> first = numbersAfter(text, "\nST(", 12);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(block.coords[i], first[i]) << i;
  for (int i = 0; i < 3; ++i) EXPECT_EQ(block.values[i], static_cast<float>(first[9 + i])) << i;

  const PosFile b = readPosFile(posFixture("magnet/b_a.pos"));
  ASSERT_EQ(b.views.size(), 1u);
  EXPECT_EQ(b.views[0].name, "b");
  EXPECT_EQ(b.views[0].components(), 3);
  EXPECT_EQ(b.views[0].elementCount(), lines);
  // The same elements, node for node.
  EXPECT_EQ(b.views[0].blocks[0].coords, block.coords);
}

TEST(PosReader, GetDPTransientStepsWithTheirTimes) {
  const PosFile file = readPosFile(posFixture("heat/t.pos"));
  ASSERT_EQ(file.views.size(), 2u);
  const PosView& t = file.views[0];
  EXPECT_EQ(t.name, "T");
  EXPECT_EQ(t.stepCount, 4);
  EXPECT_TRUE(t.timesGiven);
  EXPECT_EQ(t.times, (std::vector<double>{0, 0.01, 0.02, 0.03}));
  ASSERT_EQ(t.blocks.size(), 2u);  // triangles and quadrangles, in order of first use
  EXPECT_EQ(t.blocks[0].kind.code(), "ST");
  EXPECT_EQ(t.blocks[1].kind.code(), "SQ");
  EXPECT_EQ(t.blocks[0].elementCount(), 22u);
  EXPECT_EQ(t.blocks[1].elementCount(), 11u);
  // The plate starts at 0 and warms up under its source, its cold edge held at 0.
  for (const PosElementBlock& block : t.blocks)
    for (std::size_t e = 0; e < block.elementCount(); ++e) {
      for (int node = 0; node < block.nodesPerElement(); ++node) {
        EXPECT_EQ(t.elementValues(block, e, 0)[node], 0.0f);
        EXPECT_GE(t.elementValues(block, e, 3)[node], t.elementValues(block, e, 1)[node]);
      }
    }
  const PosView& grad = file.views[1];
  EXPECT_EQ(grad.name, "gradT");
  EXPECT_EQ(grad.components(), 3);
  EXPECT_EQ(grad.times, t.times);
  EXPECT_EQ(grad.line, 39);
  EXPECT_EQ(grad.blocks[0].coords, t.blocks[0].coords);

  // The time loop's appended views, one step each, no TIME: steps are counted from 0.
  const PosFile steps = readPosFile(posFixture("heat/steps.pos"));
  ASSERT_EQ(steps.views.size(), 3u);
  for (const PosView& view : steps.views) {
    EXPECT_EQ(view.name, "T");
    EXPECT_EQ(view.stepCount, 1);
    EXPECT_FALSE(view.timesGiven);
    EXPECT_EQ(view.elementCount(), 33u);
  }
  // The last appended view is the last step of t.pos.
  EXPECT_EQ(steps.views[2].blocks[0].values[5], t.elementValues(t.blocks[0], 1, 3)[2]);
}

TEST(PosReader, CommentsAndWhitespaceAnywhere) {
  const PosFile plain =
      readText("View \"a\" {\nST(0,0,0,1,0,0,0,1,0){1,2,3};\nST(0,0,1,1,0,1,0,1,1){4,5,6};\n};\n");
  const PosFile commented = readText(
      "// written by hand\n/* a block\n   comment */ View \"a\" { // the view\n"
      "ST ( 0 , 0,0,1,0,0, /* half way */ 0,1,0 ) { 1 ,2,\n 3 } ;\n"
      "\tST(0,0,1,1,0,1,0,1,1)\r\n{4,5,6};/**/};// end\n");
  ASSERT_EQ(commented.views.size(), 1u);
  EXPECT_EQ(commented.views[0].blocks[0].coords, plain.views[0].blocks[0].coords);
  EXPECT_EQ(commented.views[0].blocks[0].values, plain.views[0].blocks[0].values);
  EXPECT_EQ(commented.views[0].line, 3);
  EXPECT_EQ(commented.views[0].blocks[0].lines, (std::vector<std::int64_t>{4, 6}));
}

TEST(PosReader, SolverNumberFormats) {
  const PosFile file = readText(
      "View \"n\" {\nSP(1e-05,-0,+2.5){4.877771239555906e-05};\nSP(1.,.5,1E+02){-0};\n"
      "SP(0,0,0){1e-320};\nSP(0,0,0){-1e-400};\nSP(1e300,-1e-300,0){3.4e38};\n};\n");
  const PosElementBlock& block = file.views[0].blocks[0];
  EXPECT_EQ(block.coords,
            (std::vector<double>{1e-05, -0.0, 2.5, 1.0, 0.5, 100, 0, 0, 0, 0, 0, 0, 1e300, -1e-300, 0}));
  EXPECT_EQ(block.values[0], 4.877771239555906e-05f);
  EXPECT_EQ(block.values[1], 0.0f);
  EXPECT_TRUE(std::signbit(block.values[1]));
  EXPECT_EQ(block.values[2], 0.0f);  // a double's subnormal is a float's zero
  EXPECT_EQ(block.values[3], 0.0f);  // below a double's range: zero
  EXPECT_EQ(block.values[4], 3.4e38f);
}

TEST(PosReader, ViewsOfDifferentStepCountsAndComponents) {
  const PosFile file = readText(
      "View \"one\" {SP(0,0,0){1};};\nView \"two\" {SP(0,0,0){1,2};};\n"
      "View \"mixed\" {SP(0,0,0){1};VP(0,0,0){1,2,3};};\nView \"empty\" {};\n");
  ASSERT_EQ(file.views.size(), 4u);
  EXPECT_EQ(file.views[0].stepCount, 1);
  EXPECT_EQ(file.views[1].stepCount, 2);
  EXPECT_EQ(file.views[1].times, (std::vector<double>{0, 1}));
  EXPECT_EQ(file.views[2].components(), 0);  // mixed: the caller decides
  EXPECT_EQ(file.views[2].blocks.size(), 2u);
  EXPECT_EQ(file.views[3].stepCount, 0);
  EXPECT_TRUE(file.views[3].blocks.empty());
  EXPECT_TRUE(file.views[3].times.empty());
}

TEST(PosReader, NamesKeepSpacesAndEscapes) {
  const PosFile file = readText("View \"b (T) \\\"x\\\"\" {SP(0,0,0){1};};");
  EXPECT_EQ(file.views[0].name, "b (T) \"x\"");
}

}  // namespace
}  // namespace lancer
