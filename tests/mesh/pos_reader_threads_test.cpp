// A .pos file parsed in pieces on several threads gives what one thread gives: the same views,
// blocks, coordinates, values and lines, the same mesh and fields, and the same first error (file,
// line and column) wherever the pieces are cut: at elements, inside a comment that holds element
// lines, before text annotations and between views.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstring>
#include <string>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/pos/pos_reader.hpp"
#include "lancer/mesh/pos/pos_split.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

PosFile readText(const std::string& text, int threads) {
  return readPosFromMemory(std::span<const char>(text.data(), text.size()), "big.pos", threads);
}

std::string errorOf(const std::string& text, int threads) {
  return test::messageOf([&] { readText(text, threads); });
}

// Two scalar steps on the triangles of an n x n grid, one element a line, as GetDP prints them
// (%.16g); about 150 bytes an element.
std::string gridElements(int n, double shift) {
  std::string text;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x0 = i / double(n), x1 = (i + 1) / double(n), y0 = j / double(n), y1 = (j + 1) / double(n);
      const double z = shift + 1e-7 * (i * j);
      text += fmt::format(
          "ST({:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g}){{{:.16g},{:.16g},{:."
          "16g},{},{},{}}};\n",
          x0, y0, z, x1, y0, z, x1, y1, z, x0 * y0, x1 * y0 - 1, x1 * y1 + 3e-9, i, j, -i);
      text += fmt::format(
          "ST({:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g},{:.16g}){{{},{},{},{},{},{}}};"
          "\n",
          x0, y0, z, x1, y1, z, x0, y1, z, i * 0.5, j * 0.25, -1.5e-5 * i, 1, 2, 3);
    }
  return text;
}

// One view of about 3.6 MB: cut into two to four pieces at elements.
std::string plainFile() { return "View \"u\" {\nTIME{0,0.5};\n" + gridElements(110, 0) + "};\n"; }

// Two views; a comment of element lines across the middle (where two pieces would cut), a text
// annotation and a line element in the second view.
std::string awkwardFile() {
  std::string text = "// two views\nView \"u\" {\n" + gridElements(68, 0);
  text += "/* an old copy:\n" + gridElements(30, 9) + "*/\n";
  text += gridElements(40, 0.5) + "};\nView \"v\" {\nT2(10,20,0){\"label\"};\n";
  text += "SL(0,0,0,1,1,1){4,5,6,7};\n" + gridElements(60, 1) + "};\n";
  return text;
}

// `text` with the first `from` at or after `offset` replaced by `to`.
std::string replaceAfter(const std::string& text, std::size_t offset, const std::string& from,
                         const std::string& to) {
  const std::size_t at = text.find(from, offset);
  EXPECT_NE(at, std::string::npos) << from;
  return text.substr(0, at) + to + text.substr(at + from.size());
}

void expectSame(const PosFile& a, const PosFile& b) {
  ASSERT_EQ(a.views.size(), b.views.size());
  EXPECT_EQ(a.warnings, b.warnings);
  for (std::size_t v = 0; v < a.views.size(); ++v) {
    const PosView& x = a.views[v];
    const PosView& y = b.views[v];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.line, y.line);
    EXPECT_EQ(x.stepCount, y.stepCount);
    EXPECT_EQ(x.times, y.times);
    EXPECT_EQ(x.skippedTexts, y.skippedTexts);
    ASSERT_EQ(x.blocks.size(), y.blocks.size());
    for (std::size_t k = 0; k < x.blocks.size(); ++k) {
      EXPECT_EQ(x.blocks[k].kind.gmshType, y.blocks[k].kind.gmshType);
      EXPECT_EQ(x.blocks[k].coords, y.blocks[k].coords);
      EXPECT_EQ(x.blocks[k].values, y.blocks[k].values);
      EXPECT_EQ(x.blocks[k].lines, y.blocks[k].lines);
    }
  }
}

TEST(PosReaderThreads, TheTestFilesAreCutIntoPieces) {
  for (const std::string& text : {plainFile(), awkwardFile()}) {
    EXPECT_GT(text.size(), 3 * kMinPosPieceBytes);
    EXPECT_EQ(posPieceStarts(text, 3).size(), 2u);
  }
  // The middle of the awkward file is inside its comment: the cut there starts an element line.
  const std::string awkward = awkwardFile();
  const char* cut = posPieceStarts(awkward, 2).front();
  const std::size_t at = static_cast<std::size_t>(cut - awkward.data());
  EXPECT_LT(awkward.find("/* an old copy"), at);
  EXPECT_GT(awkward.find("*/"), at);
}

TEST(PosReaderThreads, PiecesGiveWhatOneThreadGives) {
  for (const std::string& text : {plainFile(), awkwardFile()}) {
    const PosFile serial = readText(text, 1);
    for (int threads : {2, 3, 4}) {
      SCOPED_TRACE(threads);
      expectSame(readText(text, threads), serial);
    }
  }
  const PosFile plain = readText(plainFile(), 1);
  EXPECT_EQ(plain.views[0].elementCount(), 2u * 110 * 110);
  EXPECT_EQ(plain.views[0].blocks[0].lines.back(), 2 + 2 * 110 * 110);
}

TEST(PosReaderThreads, MeshesAndFieldsAreTheSame) {
  const std::string text = awkwardFile();
  const Mesh serial = readMshFromMemory(std::span<const char>(text.data(), text.size()), "big.pos", 1);
  const Mesh parallel = readMshFromMemory(std::span<const char>(text.data(), text.size()), "big.pos", 3);
  ASSERT_EQ(serial.positions.size(), parallel.positions.size());
  for (std::size_t i = 0; i < serial.positions.size(); ++i)
    ASSERT_EQ(serial.positions[i], parallel.positions[i]) << i;
  ASSERT_EQ(serial.faces.size(), parallel.faces.size());
  for (std::size_t f = 0; f < serial.faces.size(); ++f)
    for (int c = 0; c < 4; ++c) ASSERT_EQ(serial.faces[f].vertex[c], parallel.faces[f].vertex[c]) << f;
  ASSERT_EQ(serial.fields.size(), parallel.fields.size());
  for (std::size_t k = 0; k < serial.fields.size(); ++k) {
    EXPECT_EQ(serial.fields[k].name, parallel.fields[k].name);
    // Bit for bit: corners without a value are NaN in both.
    const std::vector<float>& a = serial.fields[k].values;
    const std::vector<float>& b = parallel.fields[k].values;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << serial.fields[k].name;
  }
}

TEST(PosReaderThreads, TheFirstErrorInTheFileIsReported) {
  const std::string good = plainFile();
  // Errors in the last quarter and near the end (in the last piece), then one in the first half too.
  std::string late = replaceAfter(good, good.size() * 3 / 4, "0,", "0;");
  late = replaceAfter(late, late.size() * 9 / 10, "){", ")[");
  const std::string lateError = errorOf(late, 1);
  EXPECT_NE(lateError.find("big.pos:"), std::string::npos) << lateError;
  for (int threads : {2, 3, 4}) EXPECT_EQ(errorOf(late, threads), lateError) << threads;

  const std::string both = replaceAfter(late, late.size() / 3, "ST(", "SX(");
  const std::string firstError = errorOf(both, 1);
  EXPECT_NE(firstError.find("unknown element type 'SX'"), std::string::npos) << firstError;
  for (int threads : {2, 3, 4}) EXPECT_EQ(errorOf(both, threads), firstError) << threads;

  // A view whose elements change their step count in the last piece: reported at that element.
  const std::string steps = replaceAfter(good, good.size() * 4 / 5, "};", ",7};");
  const std::string stepsError = errorOf(steps, 1);
  EXPECT_NE(stepsError.find("every element of a view needs a value at each node"), std::string::npos)
      << stepsError;
  for (int threads : {2, 3, 4}) EXPECT_EQ(errorOf(steps, threads), stepsError) << threads;
}

}  // namespace
}  // namespace lancer
