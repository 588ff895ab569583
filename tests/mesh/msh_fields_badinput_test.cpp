// Broken $NodeData and $ElementData sections, made by editing a file gmsh wrote (tests/data/fields/,
// from scripts/make_field_fixtures.sh) in memory: the mesh always loads, and the section is skipped
// (or its stray values dropped) with a warning giving the file, the line (text) or byte offset
// (binary) and what is wrong.
#include <gtest/gtest.h>

#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

std::string fixture(const char* name) {
  const std::vector<char> bytes = test::readFileBytes(std::string(LANCER_TEST_DATA_DIR) + "/fields/" + name);
  return {bytes.begin(), bytes.end()};
}

using test::replaceOnce;

// The reader's first warning ("file:location: warning: ..."), or "" when it gave none; the mesh
// must load with its faces. fields: how many fields it kept.
std::string errorOf(const std::string& bytes, std::size_t* fields = nullptr) {
  return test::firstReaderWarning(bytes, "f.msh", fields);
}

const std::string kHeader = "$NodeData\n1\n\"temperature\"\n1\n-1\n3\n0\n1\n25\n";

TEST(MshFieldsBadInput, TheFixtureHeaderIsAsExpected) {
  EXPECT_NE(fixture("node_xy_v41_ascii.msh").find(kHeader + "1 0\n"), std::string::npos);
  EXPECT_NE(fixture("node_xy_v41_bin.msh").find(kHeader), std::string::npos);
  EXPECT_EQ(errorOf(fixture("node_xy_v41_ascii.msh")), "");
}

TEST(MshFieldsBadInput, MissingNode) {
  std::size_t fields = 0;
  const std::string what = errorOf(
      replaceOnce(fixture("node_xy_v41_ascii.msh"), kHeader + "1 0\n", kHeader + "9001 0\n"), &fields);
  EXPECT_EQ(what.rfind("f.msh:196:1: warning: ", 0), 0u) << what;
  EXPECT_NE(
      what.find("$NodeData 'temperature' gives values for 1 node that $Nodes does not define (the first: "
                "node 9001); they were dropped and the other 24 kept"),
      std::string::npos)
      << what;
  EXPECT_EQ(fields, 1u);
}

TEST(MshFieldsBadInput, MoreValuesThanNodes) {
  std::size_t fields = 1;
  const std::string what =
      errorOf(replaceOnce(fixture("node_xy_v22_ascii.msh"), "\n1\n25\n1 0\n", "\n1\n26\n1 0\n"), &fields);
  EXPECT_NE(what.find("warning: $NodeData \"temperature\" skipped: expected a node tag"), std::string::npos)
      << what;
  EXPECT_EQ(fields, 0u);
}

TEST(MshFieldsBadInput, ZeroComponents) {
  const std::string what = errorOf(replaceOnce(fixture("node_xy_v41_ascii.msh"), kHeader,
                                               "$NodeData\n1\n\"temperature\"\n1\n-1\n3\n0\n0\n25\n"));
  EXPECT_EQ(what.rfind("f.msh:194:", 0), 0u) << what;
  EXPECT_NE(what.find("0 components in $NodeData: expected 1 to 9"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, TooFewIntegerTags) {
  const std::string what = errorOf(replaceOnce(fixture("node_xy_v41_ascii.msh"), kHeader,
                                               "$NodeData\n1\n\"temperature\"\n1\n-1\n2\n0\n1\n"));
  EXPECT_NE(what.find("2 integer tags in $NodeData: expected at least 3"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, UnterminatedName) {
  const std::string what =
      errorOf(replaceOnce(fixture("node_xy_v41_ascii.msh"), "\"temperature\"", "\"temperature"));
  EXPECT_NE(what.find("the string tag has no closing quote"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, NonFiniteValue) {
  const std::string what =
      errorOf(replaceOnce(fixture("node_xy_v41_ascii.msh"), kHeader + "1 0\n", kHeader + "1 nan\n"));
  EXPECT_NE(what.find("non-finite value for node 1"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, TruncatedText) {
  std::string bytes = fixture("node_xy_v41_ascii.msh");
  bytes.resize(bytes.find("$EndNodeData") - 20);
  EXPECT_NE(errorOf(bytes).find("f.msh:"), std::string::npos);
}

TEST(MshFieldsBadInput, TruncatedBinary) {
  std::string bytes = fixture("node_xy_v41_bin.msh");
  bytes.resize(bytes.find(kHeader) + kHeader.size() + 100);
  const std::string what = errorOf(bytes);
  EXPECT_EQ(what.rfind("f.msh:@", 0), 0u) << what;
  EXPECT_NE(what.find("$NodeData"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, BinaryMissingNode) {
  std::string bytes = fixture("node_xy_v22_bin.msh");
  const std::size_t record = bytes.find(kHeader) + kHeader.size();
  bytes[record] = 0x7f;  // tag 1 -> 127, which the 25-node square does not have
  const std::string what = errorOf(bytes);
  EXPECT_EQ(what.rfind("f.msh:@" + std::to_string(record) + ":", 0), 0u) << what;
  EXPECT_NE(what.find("node 127"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, TruncatedElementDataBinary) {
  std::string bytes = fixture("element_xy_v41_bin.msh");
  bytes.resize(bytes.find("$ElementData") + 120);
  const std::string what = errorOf(bytes);
  EXPECT_EQ(what.rfind("f.msh:@", 0), 0u) << what;
  EXPECT_NE(what.find("$ElementData"), std::string::npos) << what;
}

TEST(MshFieldsBadInput, ElementDataNonFiniteValue) {
  const std::string what =
      errorOf(replaceOnce(fixture("element_xy_v41_ascii.msh"), "\n17 0.500000000002081\n", "\n17 inf\n"));
  EXPECT_NE(what.find("$ElementData 'temperature' has a non-finite value for element 17"), std::string::npos)
      << what;
}

TEST(MshFieldsBadInput, ElementDataBeforeElements) {
  std::string bytes = fixture("element_xy_v41_ascii.msh");
  const std::size_t data = bytes.find("$ElementData");
  const std::size_t end = bytes.find("$EndElementData") + std::string("$EndElementData\n").size();
  const std::string section = bytes.substr(data, end - data);
  bytes.erase(data, end - data);
  bytes.insert(bytes.find("$Elements"), section);
  std::size_t fields = 1;
  const std::string what = errorOf(bytes, &fields);
  EXPECT_NE(what.find("warning: $ElementData \"temperature\" skipped: $ElementData comes before $Elements"),
            std::string::npos)
      << what;
  EXPECT_EQ(fields, 0u);
}

}  // namespace
}  // namespace lancer
