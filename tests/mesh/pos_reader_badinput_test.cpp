// Broken and foreign .pos files: each is refused with an InputError at file:line:col that says what
// was expected, what was found and what to do. Most are a fixture gmsh or GetDP wrote
// (tests/data/pos/, scripts/make_pos_fixtures.py) edited in memory; truncating or corrupting one
// anywhere gives an InputError or views, never a crash or another exception.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "lancer/mesh/pos/pos_reader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string fixture(const std::string& name) { return test::readText(test::dataFile("pos/" + name)); }

std::string errorOf(const std::string& text, const std::string& name = "f.pos") {
  return test::messageOf([&] { readPosFromMemory(std::span<const char>(text.data(), text.size()), name); });
}

using test::replaceOnce;

// Adds a failure unless `message` starts with `where` ("f.pos:3:1") and ": error: ", then holds `part`.
void expectError(const std::string& message, const std::string& where, const std::string& part) {
  EXPECT_EQ(message.rfind(where + ": error: ", 0), 0u) << message;
  EXPECT_NE(message.find(part), std::string::npos) << message;
}

const std::string kMagnetFirst = "ST(-0.09567085780739318,0.2309698832454083,0,";

TEST(PosReaderBadInput, TheFixturesAreAsExpected) {
  EXPECT_EQ(fixture("magnet/az.pos").find("View \"az\" {\n" + kMagnetFirst), 0u);
  EXPECT_EQ(errorOf(fixture("magnet/az.pos")), "(no InputError)");
}

TEST(PosReaderBadInput, ValueCountNotAWholeNumberOfSteps) {
  expectError(
      errorOf("View \"a\" {\nST(0,0,0,1,0,0,0,1,0){1,2,3,4};\n};\n"), "f.pos:2:1",
      "ST (scalar triangle) takes 3 values per time step (1 component at each of its 3 nodes): found 4 "
      "values, not a whole number of steps; check the element's code and its values");
}

TEST(PosReaderBadInput, ValueCountDiffersFromTheViewsSteps) {
  // GetDP's b, its second element given a step more.
  const std::string text = fixture("magnet/b_a.pos");
  const std::size_t second = text.find("\nVT(", text.find("\nVT(") + 1) + 1;
  const std::size_t close = text.find("};", second);
  const std::string broken = text.substr(0, close) + ",1,2,3,4,5,6,7,8,9" + text.substr(close);
  expectError(
      errorOf(broken, "b_a.pos"), "b_a.pos:3:1",
      "VT (vector triangle) takes 9 values per time step (3 components at each of its 3 nodes), and "
      "view \"b\" has 1 step (as its first element has at line 2): expected 9, found 18; every element of "
      "a view needs a value at each node for every step");
  // A TIME list first (as gmsh writes it) sets the steps.
  expectError(errorOf("View \"a\" {\nTIME{0,1};\nSP(0,0,0){1};\n};\n"), "f.pos:3:1",
              "and view \"a\" has 2 steps (from its TIME list at line 2): expected 2, found 1");
}

TEST(PosReaderBadInput, TimeListOfTheWrongLength) {
  // GetDP writes TIME after the elements.
  const std::string text =
      replaceOnce(fixture("heat/t.pos"), "TIME{0,0.01,0.02,0.03};", "TIME{0,0.01,0.02};");
  expectError(
      errorOf(text, "t.pos"), "t.pos:35:1",
      "TIME gives 3 times, but the elements of view \"T\" have 4 steps (its first element at line 2): give "
      "one time per step");
  expectError(
      errorOf("View \"a\" {\nTIME{0};\nSP(0,0,0){1};\nTIME{1};\n};\n"), "f.pos:4:1",
      "view \"a\" has a second TIME list (the first is at line 2): give one list with a time per step");
}

TEST(PosReaderBadInput, UnknownElementCode) {
  const std::string help =
      "an element code is S, V or T (scalar, vector, tensor) followed by P, L, T, Q, S, H, I or Y (point, "
      "line, triangle, quadrangle, tetrahedron, hexahedron, prism, pyramid), with 2 after it for second "
      "order: ST, VQ, TS2";
  const std::string text = fixture("magnet/az.pos");
  expectError(errorOf(replaceOnce(text, kMagnetFirst, "SX" + kMagnetFirst.substr(2))), "f.pos:2:1",
              "unknown element type 'SX' in view \"az\": " + help);
  expectError(errorOf("View \"a\" {\nSP2(0,0,0){1};\n};"), "f.pos:2:1", "unknown element type 'SP2'");
  expectError(errorOf("View \"a\" {\n ST3(0,0,0){1};\n};"), "f.pos:2:2", "unknown element type 'ST3'");
  expectError(errorOf("View \"a\" {\nSG(0,0,0){1};\n};"), "f.pos:2:1", "unknown element type 'SG'");
}

TEST(PosReaderBadInput, WrongCoordinateCount) {
  expectError(
      errorOf("View \"a\" {\nST2(0,0,0,1,0,0,0,1,0){1,2,3,4,5,6};\n};"), "f.pos:2:1",
      "ST2 (scalar 6-node triangle) has 6 nodes: expected 18 coordinates (x, y, z of each node), found 9");
  expectError(errorOf("View \"a\" {\nSL(0,0,0,1,0,0,2,0,0){1,2};\n};"), "f.pos:2:1",
              "SL (scalar line) has 2 nodes: expected 6 coordinates (x, y, z of each node), found 9");
}

TEST(PosReaderBadInput, TruncatedFiles) {
  const std::string text = fixture("heat/t.pos");
  // Inside an element.
  const std::size_t cut = text.find("){") + 5;
  expectError(errorOf(text.substr(0, cut), "t.pos"), "t.pos:2:" + std::to_string(cut - text.find('\n')),
              "expected ',' or '}' in the values of this element, found the end of the file (the file looks "
              "truncated)");
  // After the last element of a view, before its '};'.
  expectError(errorOf(text.substr(0, text.find("TIME{")), "t.pos"), "t.pos:1:1",
              "the file ends inside view \"T\": expected its closing '};' (the file looks truncated)");
  // Its '}' without the ';'.
  expectError(errorOf(text.substr(0, text.rfind(';')), "t.pos"), "t.pos:74:2",
              "expected ';' after the closing '}' of view \"gradT\", found the end of the file");
  expectError(errorOf("View \"a\" { /* a comment\n that never ends"), "f.pos:1:12",
              "this /* comment is never closed: the file ends inside it (the file looks truncated)");
  expectError(errorOf("View \"a"), "f.pos:1:6", "this string is never closed");
  expectError(errorOf("View"), "f.pos:1:5",
              "expected a \"quoted\" name after View, found the end of the file");
}

TEST(PosReaderBadInput, NotANumber) {
  const std::string text = fixture("magnet/az.pos");
  const std::string nan =
      replaceOnce(text, "){0,-0.0002301885736608757,-0.0002465638807200001};", "){0,-nan,0};");
  expectError(errorOf(nan), "f.pos:2:132",
              "found '-nan', which is not a number (NaN), in the values of this element: lancer reads finite "
              "numbers only; the solver wrote no value here, check its solution");
  expectError(errorOf(replaceOnce(text, kMagnetFirst, "ST(inf,")), "f.pos:2:4",
              "found 'inf', which is infinite, in the coordinates of this element");
  expectError(errorOf("View \"a\" {\nTIME{NaN};\n};"), "f.pos:2:6",
              "found 'NaN', which is not a number (NaN), in the TIME list");
}

TEST(PosReaderBadInput, NumbersOutOfRange) {
  expectError(errorOf("View \"a\" {\nSP(0,0,0){1e39};\n};"), "f.pos:2:11",
              "the value 1e+39 is beyond the range of a float (magnitude 3.40282e+38), in which lancer keeps "
              "values: rescale the field (change its unit)");
  expectError(errorOf("View \"a\" {\nSP(0,1e999,0){1};\n};"), "f.pos:2:6",
              "the number '1e999' in the coordinates of this element is beyond the range of a double");
}

TEST(PosReaderBadInput, ExpressionsAndCommands) {
  expectError(errorOf("View \"a\" {\nSP(0,0,0){2*3};\n};"), "f.pos:2:11",
              "expected a number in the values of this element, found '2*3': lancer reads plain numbers, not "
              "gmsh expressions");
  expectError(errorOf("View \"a\" {\nSP(0,0,0){x};\n};"), "f.pos:2:11",
              "expected a number in the values of this element, found 'x'");
  expectError(
      errorOf("View \"a\" {\nFor i In {1:3}\n};"), "f.pos:2:1",
      "expected an element (ST(...){...};), TIME{...}; or the closing '};' of view \"a\", found 'For': "
      "lancer reads the lists gmsh and GetDP write, not .geo commands or expressions");
  // After an element, something that is no name at all.
  expectError(
      errorOf("View \"a\" {\nSP(0,0,0){1};\n-1;\n};"), "f.pos:3:1",
      "expected an element (ST(...){...};), TIME{...}; or the closing '};' of view \"a\", found '-1'");
  expectError(errorOf("View \"a\" {SP(0,0,0){1};};\nView[0].Visible = 0;\n"), "f.pos:2:5",
              "expected a \"quoted\" name after View, found '[0].Visible'");
  expectError(
      errorOf("View \"a\" {SP(0,0,0){1};};\nPlugin(Smooth).Run;\n"), "f.pos:2:1",
      "expected a view (View \"name\" { ... };) or the end of the file, found 'Plugin': lancer reads the "
      "views of a .pos file, not gmsh commands");
  expectError(
      errorOf("View \"a\" {\nINTERPOLATION_SCHEME{{1}}{{0}};\n};"), "f.pos:2:1",
      "view \"a\" gives its values as polynomial coefficients (INTERPOLATION_SCHEME), which lancer does "
      "not read");
}

TEST(PosReaderBadInput, EmptyAndViewlessFiles) {
  EXPECT_EQ(errorOf(""),
            "f.pos: error: the file is empty: a list-based .pos file holds views like View \"name\" "
            "{ ST(...){...}; };");
  EXPECT_EQ(errorOf("// nothing but a comment\n\n"),
            "f.pos: error: the file holds no view: a list-based .pos file holds views like View \"name\" { "
            "ST(x1,y1,z1,x2,y2,z2,x3,y3,z3){v1,v2,v3}; };");
}

TEST(PosReaderBadInput, FilesThatAreNotListBasedViews) {
  const std::string mesh = test::dataFile("pos/heat/heat.msh");
  expectError(test::messageOf([&] { readPosFile(mesh); }), mesh + ":1:1",
              "this is a gmsh mesh (.msh), not a list-based .pos view: give it to lancer as a mesh");
  std::string noise(3000, '\0');
  std::mt19937 rng(7);
  for (char& c : noise) c = static_cast<char>(rng());
  noise[0] = 'V';
  EXPECT_NE(errorOf(noise).find("f.pos: error: this is binary data (byte 0x"), std::string::npos)
      << errorOf(noise);
  EXPECT_NE(errorOf(noise).find("), not a list-based .pos file, which is text"), std::string::npos);
  expectError(errorOf("Point(1) = {0, 0, 0};\n"), "f.pos:1:1",
              "expected a view (View \"name\" { ... };) or the end of the file, found 'Point'");
}

TEST(PosReaderBadInput, GmshsOlderViewFormatsGetARecipe) {
  const std::string binary = test::dataFile("pos/binary_view.pos");
  EXPECT_EQ(
      test::messageOf([&] { readPosFile(binary); }),
      binary +
          ":1:1: error: this is a view in gmsh's older post-processing format ($PostFormat, binary version "
          "1.3), which lancer does not read: convert it to a text view by writing 'PostProcessing.Format = "
          "2; Save View[0] \"binary_view_text.pos\";' in save.geo and running 'gmsh " +
          binary + " save.geo -' (Save View[1], ... for its other views)");
  const std::string ascii = test::dataFile("pos/ascii_view.pos");
  expectError(test::messageOf([&] { readPosFile(ascii); }), ascii + ":1:1",
              "older post-processing format ($PostFormat, ASCII version 1.3)");
}

TEST(PosReaderBadInput, FilesThatCannotBeOpened) {
  EXPECT_EQ(test::messageOf([] { readPosFile("/nonexistent/az.pos"); }),
            "/nonexistent/az.pos: error: cannot open the file: No such file or directory");
  const std::string folder = test::dataFile("pos/magnet");
  EXPECT_EQ(test::messageOf([&] { readPosFile(folder); }),
            folder + ": error: is a directory, not a .pos file");
}

// Every prefix and thousands of corrupted copies of a fixture: an InputError or views, nothing else.
TEST(PosReaderBadInput, TruncatedOrCorruptedAnywhereIsAnErrorNotACrash) {
  const std::string text = fixture("gmsh_lists.pos");
  for (std::size_t size = 0; size < text.size(); size += 7) {
    try {
      readPosFromMemory(std::span<const char>(text.data(), size), "f.pos");
    } catch (const InputError&) {
    }
  }
  std::mt19937 rng(11);
  const char kBytes[] = "0123456789,;(){}\"/*-+.eE \nSTVPQ#[\0";
  for (int i = 0; i < 3000; ++i) {
    std::string copy = text;
    for (int k = 0; k < 3; ++k) {
      const std::size_t at = rng() % copy.size();
      const char byte = kBytes[rng() % (sizeof(kBytes) - 1)];
      switch (rng() % 3) {
        case 0:
          copy[at] = byte;
          break;
        case 1:
          copy.insert(copy.begin() + static_cast<std::ptrdiff_t>(at), byte);
          break;
        default:
          copy.erase(at, 1);
      }
    }
    try {
      const PosFile file = readPosFromMemory(std::span<const char>(copy.data(), copy.size()), "f.pos");
      for (const PosView& view : file.views)
        for (const PosElementBlock& block : view.blocks)
          ASSERT_EQ(block.values.size(),
                    block.elementCount() * view.stepCount * block.nodesPerElement() * block.components());
    } catch (const InputError&) {
    }
  }
}

}  // namespace
}  // namespace lancer
