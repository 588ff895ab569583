// Result steps left in their file (mesh_field.hpp: stored steps) read back exactly as the reader
// would have kept them: the same values, item for item (node data, element data, quad centres,
// text and binary, MSH 2 and 4), the same ranges; the last two steps read are kept; a file that
// changed or went away since it was read is a clear error, never other values.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/msh/stored_steps.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "support/files.hpp"
#include "support/scoped_env.hpp"

namespace lancer {
namespace {

constexpr std::uint64_t kKeepAll = UINT64_MAX;

// Bit-equal floats, NaN equal to NaN (a vertex the file gives no value).
void expectSameValues(const std::vector<float>& a, const std::vector<float>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i]) && std::isnan(b[i])) continue;
    ASSERT_EQ(a[i], b[i]) << what << ", value " << i;
  }
}

class StoredStepsFixture : public testing::TestWithParam<const char*> {};

TEST_P(StoredStepsFixture, ReadBackAsTheReaderWouldHaveKeptThem) {
  const std::string path = test::dataFile(GetParam());
  const Mesh kept = readMsh(path, 1, kKeepAll);
  const Mesh stored = readMsh(path, 1, 0);
  ASSERT_FALSE(kept.fields.empty());
  ASSERT_EQ(kept.fields.size(), stored.fields.size());
  EXPECT_EQ(kept.source.warnings, stored.source.warnings);
  for (std::size_t k = 0; k < kept.fields.size(); ++k) {
    const MeshField& a = kept.fields[k];
    const MeshField& b = stored.fields[k];
    const std::string what = fmt::format("{} field {} (\"{}\" step {})", GetParam(), k, a.name, a.step);
    EXPECT_FALSE(a.isStored()) << what;
    ASSERT_TRUE(b.isStored()) << what;
    EXPECT_TRUE(b.values.empty()) << what;
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.step, b.step);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.components, b.components);
    EXPECT_EQ(a.at, b.at);
    EXPECT_EQ(a.itemCount(), b.itemCount()) << what;
    EXPECT_EQ(a.range(), b.range()) << what;
    std::vector<FieldComponent> components{FieldComponent{}};
    for (int c = 0; c < a.components; ++c) components.push_back({FieldComponent::Kind::Index, c});
    if (a.components == 9) components.push_back({FieldComponent::Kind::VonMises, 0});
    // The ranges the reader kept are those of the values themselves.
    MeshField unranged = a;
    unranged.ranges.clear();
    EXPECT_FALSE(a.ranges.empty()) << what;
    for (const FieldComponent& component : components) {
      EXPECT_EQ(componentRange(a, component), componentRange(b, component))
          << what << ", " << describeComponent(component);
      EXPECT_EQ(componentRange(unranged, component), componentRange(a, component))
          << what << ", " << describeComponent(component);
    }
    EXPECT_EQ(unranged.range(), a.range()) << what;
    const MeshField loaded = loadedField(b);
    EXPECT_FALSE(loaded.isStored());
    expectSameValues(loaded.values, a.values, what);
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, StoredStepsFixture,
                         testing::Values("fields/node_xy_v22_ascii.msh", "fields/node_xy_v22_bin.msh",
                                         "fields/node_xy_v41_ascii.msh", "fields/node_xy_v41_bin.msh",
                                         "fields/element_xy_v22_ascii.msh", "fields/element_xy_v41_bin.msh",
                                         "fields/element_tet10_v41_bin.msh",
                                         "fields/node_quad8_v41_ascii.msh", "fields/node_vector_v41_bin.msh",
                                         "results/cantilever.msh", "results/steps/step_2.msh",
                                         "volume/capacitor.msh", "volume/cube_hex.msh"));

const MeshField& fieldAt(const Mesh& mesh, const std::string& name, int step) {
  for (const MeshField& field : mesh.fields)
    if (field.name == name && field.step == step) return field;
  throw std::runtime_error("no such field");
}

// Two steps of every view stay: a frame blending two steps of the views it colours and warps by
// reads each once.
TEST(StoredSteps, TheLastTwoStepsOfEachViewAreKept) {
  const Mesh mesh = readMsh(test::dataFile("results/cantilever.msh"), 1, 0);
  const std::size_t views = viewNames(mesh).size();
  ASSERT_GE(views, 2u);
  ASSERT_GT(mesh.fields.size(), 2 * views);
  const StoredFieldSteps& file = *mesh.fields.front().stored->file;
  EXPECT_EQ(file.fileReads(), 0u);
  for (std::size_t k = 0; k < 2 * views; ++k) loadedField(mesh.fields[k]);
  EXPECT_EQ(file.fileReads(), 2 * views);
  for (std::size_t k = 0; k < 2 * views; ++k) loadedField(mesh.fields[k]);
  EXPECT_EQ(file.fileReads(), 2 * views);  // all kept
  loadedField(mesh.fields[2 * views]);
  EXPECT_EQ(file.fileReads(), 2 * views + 1);
  loadedField(mesh.fields[1]);
  EXPECT_EQ(file.fileReads(), 2 * views + 1);  // still kept
  loadedField(mesh.fields[0]);                 // the oldest, pushed out
  EXPECT_EQ(file.fileReads(), 2 * views + 2);
  file.forgetKept();
  loadedField(mesh.fields[1]);
  EXPECT_EQ(file.fileReads(), 2 * views + 3);
}

TEST(StoredSteps, AFileChangedOrGoneSinceItWasReadIsAClearError) {
  const test::ScratchFolder folder;
  folder.copy(test::dataFile("results/cantilever.msh"), "beam.msh");
  const std::string path = folder.file("beam.msh");
  const Mesh mesh = readMsh(path, 1, 0);
  const MeshField& step = fieldAt(mesh, "displacement", 1);
  EXPECT_EQ(loadedField(step).itemCount(), mesh.positions.size());
  // The solver wrote the file again: the steps read now would not be the ones ranged.
  std::ofstream(path, std::ios::app) << "\n";
  try {
    loadedField(fieldAt(mesh, "displacement", 2));
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("the file changed since it was read"), std::string::npos) << what;
    EXPECT_NE(what.find("keep the file in place and unchanged"), std::string::npos) << what;
  }
  std::filesystem::remove(path);
  try {
    loadedField(fieldAt(mesh, "displacement", 3));
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("No such file"), std::string::npos) << error.what();
  }
}

// A script may read a relative path and change its folder before the frames read the steps back.
TEST(StoredSteps, ReadBackAfterTheWorkingFolderChanged) {
  const test::ScratchFolder folder;
  folder.copy(test::dataFile("results/cantilever.msh"), "beam.msh");
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(folder.path());
  const Mesh mesh = readMsh("beam.msh", 1, 0);
  std::filesystem::current_path(previous);
  ASSERT_TRUE(mesh.fields.front().isStored());
  EXPECT_EQ(loadedField(mesh.fields.front()).values.size(),
            mesh.fields.front().itemCount() * static_cast<std::size_t>(mesh.fields.front().components));
}

TEST(StoredSteps, TheBudgetComesFromTheEnvironment) {
  const std::string path = test::dataFile("results/cantilever.msh");
  EXPECT_EQ(defaultResidentFieldBytes(), kDefaultResidentFieldBytes);
  EXPECT_FALSE(readMsh(path).fields.front().isStored());  // a few kilobytes of steps stay
  {
    const test::ScopedEnv none("LANCER_STEP_MEMORY_MB", "0");
    EXPECT_TRUE(readMsh(path).fields.front().isStored());
  }
  {
    const test::ScopedEnv some("LANCER_STEP_MEMORY_MB", "512");
    EXPECT_EQ(defaultResidentFieldBytes(), std::uint64_t{512} << 20);
  }
  for (const char* bad : {"", "lots", "12MB", "-1", "99999999999999999999"}) {
    const test::ScopedEnv wrong("LANCER_STEP_MEMORY_MB", bad);
    try {
      readMsh(path);
      ADD_FAILURE() << "no error for '" << bad << "'";
    } catch (const InputError& error) {
      const std::string what = error.what();
      EXPECT_EQ(what.rfind("LANCER_STEP_MEMORY_MB: error: ", 0), 0u) << what;
      EXPECT_NE(what.find("is not a number of megabytes"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace lancer
