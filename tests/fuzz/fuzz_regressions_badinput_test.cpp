// Every input a fuzzer once crashed on (fuzz/regressions/<target>/) goes back through the same entry
// point: it must load or fail with a located InputError, never crash or throw anything else. Under
// LANCER_SANITIZE (scripts/ci_hardening.sh) this also catches the sanitizer reports that found them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "lancer/image/environment_map.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/input_error.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using test::readText;

std::vector<fs::path> regressionInputs(const std::string& target) {
  std::vector<fs::path> files;
  const fs::path folder = fs::path(LANCER_SOURCE_DIR) / "fuzz" / "regressions" / target;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().filename() != "README.md" &&
        entry.path().filename().string().front() != '.')
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FuzzRegressions, MshReaderInputsFailCleanly) {
  const std::vector<fs::path> inputs = regressionInputs("msh_reader");
  ASSERT_FALSE(inputs.empty());
  for (const fs::path& path : inputs) {
    SCOPED_TRACE(path.filename().string());
    const std::string bytes = readText(path);
    try {
      (void)readMshFromMemory(std::span(bytes.data(), bytes.size()), "fuzz.msh");
    } catch (const InputError& e) {
      EXPECT_EQ(e.location().file, "fuzz.msh");
      EXPECT_FALSE(e.message().empty());
    }
  }
}

// The first finding: a v4.1 binary $Nodes block with zero nodes made copyRaw call memcpy with the
// empty vector's null data() (UBSan: null pointer passed as argument 1). It is a valid empty block.
TEST(FuzzRegressions, EmptyBinaryNodeBlockIsNotUndefinedBehaviour) {
  const std::string bytes =
      readText(fs::path(LANCER_SOURCE_DIR) / "fuzz/regressions/msh_reader/empty_node_block_memcpy_null.msh");
  try {
    (void)readMshFromMemory(std::span(bytes.data(), bytes.size()), "fuzz.msh");
  } catch (const InputError& e) {
    EXPECT_EQ(e.location().file, "fuzz.msh") << e.what();
  }
}

TEST(FuzzRegressions, SceneLoaderInputsFailCleanly) {
  for (const fs::path& path : regressionInputs("scene_loader")) {
    SCOPED_TRACE(path.filename().string());
    try {
      (void)parseScene(readText(path), "/fuzz/scene.toml");
    } catch (const InputError& e) {
      EXPECT_EQ(e.location().file, "/fuzz/scene.toml");
    }
  }
}

TEST(FuzzRegressions, ExrMapInputsFailCleanly) {
  for (const fs::path& path : regressionInputs("exr_map")) {
    SCOPED_TRACE(path.filename().string());
    try {
      (void)readEnvironmentMap(path.string());
    } catch (const InputError& e) {
      EXPECT_EQ(e.location().file, path.string());
    }
  }
}

}  // namespace
}  // namespace lancer
