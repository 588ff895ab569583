// The scene loader on a TOML document in memory (sceneFromToml: what Python's lancer.Scene builds)
// and meshes given in memory in place of their files (readSceneMeshes with `given`).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "lancer/mesh/mesh_file.hpp"
#include "lancer/mesh/msh_reader.hpp"
#include "lancer/scene/results/step_files.hpp"
#include "lancer/scene/scene.hpp"
#include "lancer/scene/scene_from_toml.hpp"
#include "lancer/scene/scene_loader.hpp"

namespace lancer {
namespace {

const std::string kBracket = LANCER_TEST_DATA_DIR "/render/bracket_coarse.msh";
const std::string kCapacitor = LANCER_TEST_DATA_DIR "/volume/capacitor.msh";

std::string messageOf(const toml::table& document, const std::string& where) {
  try {
    sceneFromToml(document, where, "");
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SceneFromToml, ReadsWhatTheSameTextGives) {
  const std::string text =
      "[render]\nwidth = 120\nheight = 80\n[[light]]\ntype = \"sun\"\ndirection = [0, 1, 1]\n"
      "[[mesh]]\nfile = \"part.msh\"\nrotate = [0, 30, 0]\n";
  const SceneDescription parsed = parseScene(text, "folder/scene.toml");
  const SceneDescription read = sceneFromToml(toml::parse(text), "Scene", "folder");
  EXPECT_EQ(read.render.width, parsed.render.width);
  EXPECT_EQ(read.render.height, parsed.render.height);
  ASSERT_EQ(read.lights.size(), 1u);
  ASSERT_EQ(read.meshes.size(), 1u);
  EXPECT_EQ(read.meshes[0].file, parsed.meshes[0].file);  // resolved against the folder given
  EXPECT_EQ(read.meshes[0].file, "folder/part.msh");
  EXPECT_EQ(read.path, "Scene");
}

TEST(SceneFromToml, KeysBuiltInCodeAreCheckedAsAFileIsNamingTheCaller) {
  // Nodes made in code have no source position: the message names the caller, without a line.
  toml::table render{{"width", 0}};
  const std::string width = messageOf(toml::table{{"render", render}}, "set");
  EXPECT_EQ(width.rfind("set: error: render.width must be between 1 and ", 0), 0u) << width;
  toml::table mesh{{"file", "part.msh"}, {"smooth_angel", 30}};
  const std::string unknown = messageOf(toml::table{{"mesh", toml::array{mesh}}}, "add_mesh");
  EXPECT_NE(unknown.find("add_mesh: error: unknown key 'smooth_angel' in mesh[0]"), std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find("did you mean 'smooth_angle'?"), std::string::npos) << unknown;
}

TEST(ReadSceneMeshes, AGivenMeshStandsForItsFile) {
  toml::table entry{{"file", "<arrays>"}};
  const SceneDescription description =
      sceneFromToml(toml::table{{"mesh", toml::array{entry, toml::table{{"file", kBracket}}}}}, "Scene", "");
  const auto given = std::make_shared<const Mesh>(readMsh(kBracket));
  const std::vector<std::shared_ptr<const Mesh>> meshes = {given, nullptr};
  const std::vector<Mesh> read = readSceneMeshes(description, 1, nullptr, nullptr, meshes);
  ASSERT_EQ(read.size(), 2u);
  EXPECT_EQ(read[0].faces.size(), given->faces.size());
  EXPECT_EQ(read[1].faces.size(), given->faces.size());  // the second read from its file
  // Without the given mesh, "<arrays>" is a file that does not exist.
  EXPECT_THROW(readSceneMeshes(description), InputError);
}

TEST(ReadSceneMeshes, AGivenMeshHasNoVolumeToSlice) {
  toml::table slice{{"point", toml::array{0, 0, 0}}, {"normal", toml::array{0, 0, 1}}};
  toml::table entry{{"file", "<arrays>"}, {"slice", toml::array{slice}}};
  const SceneDescription description =
      sceneFromToml(toml::table{{"mesh", toml::array{entry}}}, "add_mesh", "");
  const std::vector<std::shared_ptr<const Mesh>> meshes = {std::make_shared<const Mesh>(readMsh(kBracket))};
  try {
    readSceneMeshes(description, 1, nullptr, nullptr, meshes);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is a mesh in memory without volume elements"),
              std::string::npos)
        << error.what();
  }
}

TEST(ReadSceneMeshes, AGivenMeshDrawsInsideTheVolumeItsFileHolds) {
  // A mesh read from its file without its volume (Python's lancer.read_msh), given with the volume
  // the caller read for it: its slice is drawn inside that volume, as from the file's path.
  toml::table slice{{"point", toml::array{0, 0, 0}}, {"normal", toml::array{0, 0, 1}}};
  toml::table entry{{"file", "<arrays>"}, {"slice", toml::array{slice}}};
  const SceneDescription description =
      sceneFromToml(toml::table{{"mesh", toml::array{entry}}}, "add_mesh", "");
  MeshWithVolume file = readMeshFileWithVolume(kCapacitor, 1);
  ASSERT_TRUE(file.volume && !file.volume->empty());
  const std::vector<std::shared_ptr<const Mesh>> meshes = {std::make_shared<const Mesh>(file.mesh)};
  const std::vector<std::shared_ptr<const VolumeMesh>> fileVolumes = {file.volume};
  std::vector<std::shared_ptr<const VolumeMesh>> volumes;
  const std::vector<Mesh> read = readSceneMeshes(description, 1, nullptr, &volumes, meshes, fileVolumes);
  ASSERT_EQ(volumes.size(), 1u);
  EXPECT_EQ(volumes[0], file.volume);
  EXPECT_EQ(read[0].volume, file.volume);
}

}  // namespace
}  // namespace lancer
