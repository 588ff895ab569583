// Broken $ElementNodeData sections, made by editing files GetDP and gmsh wrote (tests/data/getdp/,
// tests/data/element_node/) in memory: the mesh always loads, and the section is skipped (or its
// stray records dropped) with a warning giving the file, the line (text) or byte offset (binary) and
// what is wrong.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string fixture(const std::string& name) {
  const std::vector<char> bytes = test::readFileBytes(test::dataFile(name));
  return {bytes.begin(), bytes.end()};
}

using test::replaceOnce;

// The reader's first warning, or "" when it gave none; the mesh must load with its faces.
std::string warningOf(const std::string& bytes, std::size_t* fields = nullptr) {
  return test::firstReaderWarning(bytes, "az.pos", fields);
}

const std::string kAz = "getdp/magnet_v2_az.pos";
const std::string kFirstRecord = "\n59 3 -0.0004983016887074152 ";

TEST(ElementNodeDataBadInput, TheFixtureIsAsExpected) {
  std::size_t fields = 0;
  EXPECT_EQ(warningOf(fixture(kAz), &fields), "");
  EXPECT_EQ(fields, 1u);
  EXPECT_NE(fixture(kAz).find(kFirstRecord), std::string::npos);
}

TEST(ElementNodeDataBadInput, NoNodes) {
  std::size_t fields = 1;
  const std::string what =
      warningOf(replaceOnce(fixture(kAz), kFirstRecord, "\n59 0 -0.0004983016887074152 "), &fields);
  EXPECT_EQ(what.rfind("az.pos:926:4: warning: $ElementNodeData \"az\" skipped: an element with 0 nodes in "
                       "$ElementNodeData: expected 1 to 1000",
                       0),
            0u)
      << what;
  EXPECT_EQ(fields, 0u);
}

TEST(ElementNodeDataBadInput, TooFewValues) {
  // The first record gives 2 values for 3 nodes: the third is read from the next record's tag, and
  // the section ends one value early.
  const std::string what = warningOf(
      replaceOnce(fixture(kAz), kFirstRecord + "-0.000309799197862804 ", "\n59 3 -0.0004983016887074152 "));
  EXPECT_NE(what.find("$ElementNodeData \"az\" skipped:"), std::string::npos) << what;
}

TEST(ElementNodeDataBadInput, NonFiniteValue) {
  const std::string what = warningOf(replaceOnce(fixture(kAz), kFirstRecord, "\n59 3 nan "));
  EXPECT_NE(what.find("az.pos:926:6: warning: $ElementNodeData \"az\" skipped: $ElementNodeData 'az' has a "
                      "non-finite value for element 59"),
            std::string::npos)
      << what;
}

TEST(ElementNodeDataBadInput, UnknownElement) {
  std::size_t fields = 0;
  const std::string what =
      warningOf(replaceOnce(fixture(kAz), kFirstRecord, "\n99999 3 -0.0004983016887074152 "), &fields);
  EXPECT_NE(
      what.find("az.pos:926:1: warning: $ElementNodeData 'az' gives values for 1 element that $Elements "
                "does not hold (the first: element 99999); they were dropped and the other 583 kept"),
      std::string::npos)
      << what;
  EXPECT_EQ(fields, 1u);
}

TEST(ElementNodeDataBadInput, BeforeElements) {
  std::string bytes = fixture(kAz);
  const std::size_t data = bytes.find("$ElementNodeData");
  const std::size_t end = bytes.find("$EndElementNodeData") + std::string("$EndElementNodeData\n").size();
  const std::string section = bytes.substr(data, end - data);
  bytes.erase(data, end - data);
  bytes.insert(bytes.find("$Elements"), section);
  std::size_t fields = 1;
  const std::string what = warningOf(bytes, &fields);
  EXPECT_NE(what.find("warning: $ElementNodeData \"az\" skipped: $ElementNodeData comes before $Elements"),
            std::string::npos)
      << what;
  EXPECT_EQ(fields, 0u);
}

TEST(ElementNodeDataBadInput, TruncatedBinary) {
  std::string bytes = fixture("element_node/tet_v41_bin.msh");
  bytes.resize(bytes.find("$ElementNodeData") + 200);
  const std::string what = warningOf(bytes);
  EXPECT_EQ(what.rfind("az.pos:@", 0), 0u) << what;
  EXPECT_NE(what.find("$ElementNodeData"), std::string::npos) << what;
}

TEST(ElementNodeDataBadInput, AbsurdNodeCountInBinary) {
  // The first record's node count (after its 4-byte tag) says two billion nodes.
  std::string bytes = fixture("element_node/tet_v41_bin.msh");
  std::size_t at = bytes.find("$ElementNodeData");
  ASSERT_NE(at, std::string::npos);
  for (int line = 0; line < 10; ++line) at = bytes.find('\n', at) + 1;  // the name and 9 header lines
  const std::int32_t huge = 2'000'000'000;
  bytes.replace(at + 4, 4, reinterpret_cast<const char*>(&huge), 4);
  const std::string what = warningOf(bytes);
  EXPECT_NE(what.find("an element with 2000000000 nodes in $ElementNodeData"), std::string::npos) << what;
}

}  // namespace
}  // namespace lancer
