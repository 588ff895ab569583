// `lancer render --legend FILE`: writes the colour bar of the first field-coloured mesh beside the
// picture, and refuses (exit 2, nothing written) when no mesh is coloured.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "lancer/image/color_map.hpp"
#include "lancer/image/image_io.hpp"

namespace lancer {
namespace {

int run(const std::string& arguments, std::string& output) {
  const std::string command = std::string("'") + LANCER_CLI_PATH + "' " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) output.append(buffer, got);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string kRender = LANCER_TEST_DATA_DIR "/render/";

TEST(LegendCli, WritesTheColourBarOfTheColouredMesh) {
  const auto dir = std::filesystem::temp_directory_path() / ("lancer_legend_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string output;
  const int code = run("render '" + kRender + "field_square.toml' -q -o '" + (dir / "a.png").string() +
                           "' --legend '" + (dir / "legend.png").string() + "'",
                       output);
  ASSERT_EQ(code, 0) << output;
  const Image legend = readPng((dir / "legend.png").string());
  // field_square.toml colours with magma over [0.5, 3]: the bar is the one colorBarImage draws.
  const Image expected = colorBarImage(ColorMapKind::Magma, 0.5, 3, legend.width(), legend.height());
  ASSERT_EQ(legend.width(), expected.width());
  EXPECT_EQ(encodeImage8(legend, TransferCurve::Linear, 3), encodeImage8(expected, TransferCurve::Linear, 3));
  std::filesystem::remove_all(dir);
}

TEST(LegendCli, NeedsAColouredMesh) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("lancer_legend_none_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string output;
  const int code = run("render '" + kRender + "bracket_ortho.toml' -q -o '" + (dir / "a.png").string() +
                           "' --legend '" + (dir / "legend.png").string() + "'",
                       output);
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find("--legend needs a mesh coloured by a field"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "legend.png"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lancer
