// `lancer info --accel` and `lancer render --accel` through the built CLI: the build statistics in
// text and JSON, every accelerator name accepted, and the build's thread count not changing the image.
#include <gtest/gtest.h>

#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::CommandResult;
using test::contains;
using test::runCli;

const std::string kFixture = test::quoted(test::dataFile("accel/holed_block.msh"));

TEST(InfoAccelCli, BareFlagDescribesTheDefaultBvh) {
  const CommandResult result = runCli("info " + kFixture + " --accel");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  test::expectContainsAll(
      result.output, {"accelerator:     bvh over ", "  nodes:", "  depth:", "  faces/leaf:", "  SAH cost:",
                      "  build time:", "  memory:", "bytes/triangle"});
}

TEST(InfoAccelCli, NamedBuildAndJson) {
  const CommandResult text = runCli("info " + kFixture + " --accel kdtree-median");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(contains(text.output, "accelerator:     kdtree-median over ")) << text.output;
  const CommandResult json = runCli("info " + kFixture + " --json --accel naive");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  test::expectContainsAll(json.output, {"\"accel\": {\"kind\": \"naive\", ", "\"bytesPerTriangle\": "});
  const CommandResult plain = runCli("info " + kFixture);
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_FALSE(contains(plain.output, "accelerator:")) << plain.output;
}

TEST(InfoAccelCli, UnknownKindIsAUsageError) {
  const CommandResult result = runCli("info " + kFixture + " --accel octree");
  EXPECT_NE(result.exitCode, 0);
  EXPECT_TRUE(contains(result.output, "octree")) << result.output;
  test::expectContainsAll(result.output, {"bvh", "kdtree-sah", "kdtree-sah-exact", "kdtree-median", "naive"});
}

TEST(InfoAccelCli, ExactSahBuildIsSelectable) {
  const CommandResult text = runCli("info " + kFixture + " --accel kdtree-sah-exact");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(contains(text.output, "accelerator:     kdtree-sah-exact over ")) << text.output;
}

TEST(RenderAccelCli, ExactBuildAndAnyThreadCountRenderTheSameImage) {
  test::ScratchFolder folder;
  auto render = [&](const std::string& options, const std::string& name) {
    const CommandResult result = runCli("render -q " + kFixture + " --width 64 --height 48 " + options +
                                        " -o " + test::quoted(folder.file(name)));
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return folder.file(name);
  };
  const std::string one = render("--threads 1", "one.png");
  test::expectSameFile(render("--threads 2", "two.png"), one);
  test::expectSameFile(render("--accel kdtree-sah-exact --threads 2", "exact.png"), one);
  test::expectSameFile(render("--accel kdtree-sah --threads 3", "kd.png"), one);
  test::expectSameFile(render("--accel bvh --threads 4", "bvh.png"), one);
  const CommandResult bad =
      runCli("render -q " + kFixture + " --accel octree -o " + test::quoted(folder.file("x.png")));
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  test::expectContainsAll(bad.output,
                          {"octree", "bvh", "kdtree-sah", "kdtree-sah-exact", "kdtree-median", "naive"});
}

}  // namespace
}  // namespace lancer
