// `lancer info` lists the fields of a file with $NodeData (text and --json), through the built CLI.
#include <gtest/gtest.h>

#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::CommandResult;
using test::quoted;
using test::runCli;

const std::string kFile = quoted(test::dataFile("fields/node_xy_v41_bin.msh"));
const std::string kNoFields = quoted(test::mshFixture("square_tri3_v41_ascii.msh"));

TEST(InfoFields, TextListsTheField) {
  const CommandResult result = runCli("info " + kFile);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  // x + 2 y over the unit square spans 0 .. 3.
  test::expectContainsAll(
      result.output,
      {"fields:\n  \"temperature\"            node data, 1 component, step 0 (time -1), values 0 .. 3\n"});
}

TEST(InfoFields, JsonListsTheField) {
  const CommandResult result = runCli("info " + kFile + " --json");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  test::expectContainsAll(
      result.output,
      {"\"fields\": [\n    {\"name\": \"temperature\", \"location\": \"node\", \"components\": 1, "
       "\"step\": 0, \"time\": -1, \"min\": 0, \"max\": 3}\n  ],"});
}

TEST(InfoFields, NoFieldsGivesAnEmptyJsonList) {
  const CommandResult result = runCli("info " + kNoFields + " --json");
  const std::string& out = result.output;
  ASSERT_EQ(result.exitCode, 0) << out;
  EXPECT_NE(out.find("\"fields\": [],"), std::string::npos) << out;
  EXPECT_EQ(runCli("info " + kNoFields).output.find("fields:"), std::string::npos);
}

// A result whose steps stay in the file says so (forced here with a budget of 0 MB); one read into
// memory does not.
TEST(InfoFields, SaysWhenTheStepsStayInTheFile) {
  const std::string beam = quoted(test::dataFile("results/cantilever.msh"));
  const CommandResult stored = runCli("info " + beam, "env LANCER_STEP_MEMORY_MB=0");
  ASSERT_EQ(stored.exitCode, 0) << stored.output;
  EXPECT_NE(stored.output.find(
                "stay in the file and are read when a picture needs them (LANCER_STEP_MEMORY_MB: 0 MB)"),
            std::string::npos)
      << stored.output;
  const CommandResult kept = runCli("info " + beam);
  ASSERT_EQ(kept.exitCode, 0) << kept.output;
  EXPECT_EQ(kept.output.find("stay in the file"), std::string::npos) << kept.output;
}

}  // namespace
}  // namespace lancer
