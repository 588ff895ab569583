// `lancer info --accel` through the built CLI: the build statistics of issue 4 in text and JSON.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace lancer {
namespace {

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

CommandResult runCli(const std::string& arguments) {
  const std::string command = std::string("'") + LANCER_CLI_PATH + "' " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, got);
  const int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kFixture = std::string("'") + LANCER_TEST_DATA_DIR + "/accel/holed_block.msh'";

TEST(InfoAccelCli, BareFlagDescribesTheSahTree) {
  const CommandResult result = runCli("info " + kFixture + " --accel");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::string& out = result.output;
  EXPECT_TRUE(contains(out, "accelerator:     kdtree-sah over ")) << out;
  for (const char* field : {"  nodes:", "  depth:", "  faces/leaf:", "  SAH cost:", "  build time:", "  memory:"}) {
    EXPECT_TRUE(contains(out, field)) << field << "\n" << out;
  }
  EXPECT_TRUE(contains(out, "bytes/triangle")) << out;
}

TEST(InfoAccelCli, NamedBuildAndJson) {
  const CommandResult text = runCli("info " + kFixture + " --accel kdtree-median");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(contains(text.output, "accelerator:     kdtree-median over ")) << text.output;
  const CommandResult json = runCli("info " + kFixture + " --json --accel naive");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  EXPECT_TRUE(contains(json.output, "\"accel\": {\"kind\": \"naive\", ")) << json.output;
  EXPECT_TRUE(contains(json.output, "\"bytesPerTriangle\": ")) << json.output;
  const CommandResult plain = runCli("info " + kFixture);
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_FALSE(contains(plain.output, "accelerator:")) << plain.output;
}

TEST(InfoAccelCli, UnknownKindIsAUsageError) {
  const CommandResult result = runCli("info " + kFixture + " --accel octree");
  EXPECT_NE(result.exitCode, 0);
  EXPECT_TRUE(contains(result.output, "octree")) << result.output;
}

}  // namespace
}  // namespace lancer
