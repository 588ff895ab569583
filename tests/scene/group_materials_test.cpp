// A scene's `groups = { ... }` on a mesh whose faces are in several physical groups (gmsh-made
// tests/data/reader/two_plates_groups_*.msh: left square in "left" and "both", right square in
// "both" and "right_flipped"): the most specific mapping wins, the group with the fewest faces,
// and of groups of equal size the mapping written last.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/scene.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

std::string readerFixture(const std::string& name) {
  return std::string(LANCER_TEST_DATA_DIR) + "/reader/" + name;
}

// Materials 0 (default), 1, 2, 3; mappings (group, material) in file order.
std::vector<std::uint32_t> faceMaterials(const char* file,
                                         const std::vector<std::pair<std::string, int>>& groups) {
  SceneDescription description;
  description.materials.resize(4);
  MeshInstance instance;
  instance.file = readerFixture(file);
  int line = 10;
  for (const auto& [group, material] : groups)
    instance.groupMaterials.push_back({group, material, SourceLocation{"scene.toml", line++, 1}});
  description.meshes.push_back(instance);
  return test::sceneFromMeshes(description, {readMsh(instance.file)}).appearance.faceMaterial;
}

// (left square's material, right square's material), every face of a square the same.
std::pair<std::uint32_t, std::uint32_t> squareMaterials(
    const char* file, const std::vector<std::pair<std::string, int>>& groups) {
  const Mesh mesh = readMsh(readerFixture(file));
  const std::vector<std::uint32_t> materials = faceMaterials(file, groups);
  std::set<std::uint32_t> left, right;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    (mesh.worldPosition(mesh.faces[f].vertex[0]).x < 1.5 ? left : right).insert(materials[f]);
  EXPECT_EQ(left.size(), 1u);
  EXPECT_EQ(right.size(), 1u);
  return {*left.begin(), *right.begin()};
}

TEST(GroupMaterials, TheMostSpecificGroupWinsWhateverTheOrder) {
  for (const char* file : {"two_plates_groups_v41_bin.msh", "two_plates_groups_v22_ascii.msh"}) {
    SCOPED_TRACE(file);
    using Result = std::pair<std::uint32_t, std::uint32_t>;
    EXPECT_EQ(squareMaterials(file, {{"both", 1}, {"left", 2}}), Result(2, 1));
    EXPECT_EQ(squareMaterials(file, {{"left", 2}, {"both", 1}}), Result(2, 1));
    EXPECT_EQ(squareMaterials(file, {{"right_flipped", 3}, {"both", 1}}), Result(1, 3));
    EXPECT_EQ(squareMaterials(file, {{"3", 3}, {"both", 1}, {"left", 2}}), Result(2, 3));  // by tag
    // Equal sizes (the same group named twice, by name and tag): the later mapping.
    EXPECT_EQ(squareMaterials(file, {{"both", 1}, {"2", 2}}), Result(2, 2));
    EXPECT_EQ(squareMaterials(file, {{"2", 2}, {"both", 1}}), Result(1, 1));
    EXPECT_EQ(squareMaterials(file, {{"left", 2}}), Result(2, 0));
  }
}

}  // namespace
}  // namespace lancer
