// `lancer info` lists the fields of a file with $NodeData (text and --json), through the built CLI.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace lancer {
namespace {

std::string runInfo(const std::string& arguments, int& exitCode) {
  const std::string command = std::string("'") + LANCER_CLI_PATH + "' info " + arguments + " 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return output;
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) output.append(buffer, got);
  const int status = pclose(pipe);
  exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return output;
}

const std::string kFile = std::string("'") + LANCER_TEST_DATA_DIR + "/fields/node_xy_v41_bin.msh'";

TEST(InfoFields, TextListsTheField) {
  int code = -1;
  const std::string out = runInfo(kFile, code);
  ASSERT_EQ(code, 0) << out;
  // x + 2 y over the unit square spans 0 .. 3.
  EXPECT_NE(
      out.find(
          "fields:\n  \"temperature\"            node data, 1 component, step 0 (time -1), values 0 .. 3\n"),
      std::string::npos)
      << out;
}

TEST(InfoFields, JsonListsTheField) {
  int code = -1;
  const std::string out = runInfo(kFile + " --json", code);
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(
      out.find("\"fields\": [\n    {\"name\": \"temperature\", \"location\": \"node\", \"components\": 1, "
               "\"step\": 0, \"time\": -1, \"min\": 0, \"max\": 3}\n  ],"),
      std::string::npos)
      << out;
}

TEST(InfoFields, NoFieldsGivesAnEmptyJsonList) {
  int code = -1;
  const std::string out =
      runInfo(std::string("'") + LANCER_TEST_DATA_DIR + "/msh/square_tri3_v41_ascii.msh' --json", code);
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("\"fields\": [],"), std::string::npos) << out;
  EXPECT_EQ(runInfo(std::string("'") + LANCER_TEST_DATA_DIR + "/msh/square_tri3_v41_ascii.msh'", code)
                .find("fields:"),
            std::string::npos);
}

}  // namespace
}  // namespace lancer
