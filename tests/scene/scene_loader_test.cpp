// The scene loader on good input: every key of the contract reaches SceneDescription, absent keys
// take their documented defaults, and relative paths are resolved against the scene file's folder.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "lancer/scene/scene_loader.hpp"

namespace lancer {
namespace {

const std::string kDataDir = LANCER_TEST_DATA_DIR "/scene";

void expectVec(const Vec3& actual, float x, float y, float z) {
  EXPECT_FLOAT_EQ(actual.x, x);
  EXPECT_FLOAT_EQ(actual.y, y);
  EXPECT_FLOAT_EQ(actual.z, z);
}

void expectVec(const Vec3d& actual, double x, double y, double z) {
  EXPECT_DOUBLE_EQ(actual.x, x);
  EXPECT_DOUBLE_EQ(actual.y, y);
  EXPECT_DOUBLE_EQ(actual.z, z);
}

// The fields the tests below check, as one comparable value (the loader stores what the file wrote,
// converted once to float, so the values compare exactly).
auto renderFields(const RenderSettings& r) {
  return std::tie(r.width, r.height, r.samples, r.maxDepth, r.sampler, r.shading, r.background,
                  r.transparentBackground, r.srgb, r.output);
}
auto materialFields(const Material& m) {
  return std::tie(m.name, m.ka, m.kd, m.ks, m.shininess, m.reflectivity, m.transparency, m.ior, m.fresnel,
                  m.absorption);
}
void expectRender(const RenderSettings& actual, const RenderSettings& expected) {
  EXPECT_EQ(renderFields(actual), renderFields(expected));
}
void expectMaterial(const Material& actual, const Material& expected) {
  EXPECT_EQ(materialFields(actual), materialFields(expected));
}

// The built-in material (docs/scene_file.md's defaults): neither reflective nor transparent.
void expectDefaultMaterial(const Material& material) {
  expectMaterial(material, Material{.name = "default",
                                    .ka = {0.2f, 0.2f, 0.2f},
                                    .kd = {0.7f, 0.7f, 0.7f},
                                    .ks = {0.3f, 0.3f, 0.3f},
                                    .shininess = 32});
  EXPECT_FLOAT_EQ(material.ior, 1.5f);
}

TEST(SceneLoader, FullSceneSetsEveryField) {
  const std::string path = kDataDir + "/full_scene.toml";
  const SceneDescription scene = loadScene(path);
  EXPECT_EQ(scene.path, path);

  expectRender(scene.render, RenderSettings{.width = 320,
                                            .height = 240,
                                            .samples = 9,
                                            .maxDepth = 7,
                                            .sampler = SamplerKind::Stratified,
                                            .shading = ShadingMode::Gouraud,
                                            .background = {0.25f, 0.5f, 1.0f},
                                            .output = kDataDir + "/renders/full.png",
                                            .srgb = true});

  const CameraSettings& camera = scene.camera;
  EXPECT_EQ(camera.projection, Projection::Orthographic);
  ASSERT_TRUE(camera.position);
  expectVec(*camera.position, 3, 2, 5);
  ASSERT_TRUE(camera.lookAt);
  expectVec(*camera.lookAt, 0, 0.5, 0);
  expectVec(camera.up, 0, 0, 1);
  EXPECT_DOUBLE_EQ(camera.fovDegrees, 55.5);
  ASSERT_TRUE(camera.viewHeight);
  EXPECT_DOUBLE_EQ(*camera.viewHeight, 2.5);

  expectVec(scene.ambient, 0.1f, 0.2f, 0.3f);

  ASSERT_EQ(scene.lights.size(), 2u);
  expectVec(scene.lights[0].position, 5, 5, 5);
  expectVec(scene.lights[0].intensity, 1, 0.9f, 0.8f);
  expectVec(scene.lights[0].attenuation, 1, 0.5f, 0.25f);
  expectVec(scene.lights[1].position, -2, 4, 1.5);
  expectVec(scene.lights[1].intensity, 1, 1, 1);
  expectVec(scene.lights[1].attenuation, 1, 0, 0);

  // The built-in default first, then the file's materials in file order (not alphabetical).
  ASSERT_EQ(scene.materials.size(), 3u);
  expectDefaultMaterial(scene.materials[0]);
  expectMaterial(scene.materials[1], Material{.name = "steel",
                                              .ka = {0.2f, 0.25f, 0.3f},
                                              .kd = {0.5f, 0.5f, 0.55f},
                                              .ks = {0.8f, 0.8f, 0.8f},
                                              .shininess = 50,
                                              .reflectivity = {0.1f, 0.2f, 0.3f},
                                              .transparency = 0.25f,
                                              .ior = 1.33f,
                                              .fresnel = true,
                                              .absorption = {0.5f, 0.25f, 0}});
  const Material& glass = scene.materials[2];
  EXPECT_EQ(glass.name, "glass");
  expectVec(glass.reflectivity, 0.1f, 0.1f, 0.1f);  // a number means the same for every channel
  EXPECT_FLOAT_EQ(glass.transparency, 0.9f);
  expectVec(glass.kd, 0.7f, 0.7f, 0.7f);  // keys it leaves out keep the default material's values
  EXPECT_FLOAT_EQ(glass.ior, 1.5f);

  ASSERT_EQ(scene.meshes.size(), 2u);
  const MeshInstance& part = scene.meshes[0];
  EXPECT_EQ(part.file, kDataDir + "/meshes/part.msh");
  EXPECT_EQ(part.where.file, path);
  EXPECT_EQ(part.where.line, 48);
  EXPECT_EQ(part.where.column, 1);
  EXPECT_EQ(part.material, 1);
  ASSERT_TRUE(part.shading);
  EXPECT_EQ(*part.shading, ShadingMode::Flat);
  EXPECT_FLOAT_EQ(part.smoothAngleDegrees, 30);
  expectVec(part.translate, 1, -2, 3.5);
  expectVec(part.rotateDegrees, 90, 0, -45);
  expectVec(part.scale, 2, 3, 0.5);
  // Group entries keep the order of the file and the location of their key.
  ASSERT_EQ(part.groupMaterials.size(), 3u);
  EXPECT_EQ(part.groupMaterials[0].group, "Window");
  EXPECT_EQ(part.groupMaterials[0].material, 2);
  EXPECT_EQ(part.groupMaterials[0].where.line, 56);
  EXPECT_EQ(part.groupMaterials[0].where.column, 12);
  EXPECT_EQ(part.groupMaterials[1].group, "7");
  EXPECT_EQ(part.groupMaterials[1].material, 1);
  EXPECT_EQ(part.groupMaterials[2].group, "Floor");
  EXPECT_EQ(part.groupMaterials[2].material, 0);

  const MeshInstance& floor = scene.meshes[1];
  EXPECT_EQ(floor.file, "/abs/floor.msh");  // absolute paths are kept
  EXPECT_EQ(floor.material, 0);
  EXPECT_FALSE(floor.shading);
  EXPECT_FLOAT_EQ(floor.smoothAngleDegrees, 60);
  expectVec(floor.translate, 0, 0, 0);
  expectVec(floor.rotateDegrees, 0, 0, 0);
  expectVec(floor.scale, 4, 4, 4);
  EXPECT_TRUE(floor.groupMaterials.empty());

  ASSERT_TRUE(scene.animation);
  const AnimationSettings& animation = *scene.animation;
  EXPECT_EQ(animation.frames, 24);
  EXPECT_DOUBLE_EQ(animation.fps, 8.5);
  EXPECT_EQ(animation.orbitLight, 1);
  ASSERT_TRUE(animation.axis);
  expectVec(*animation.axis, 0, 0, 1);
  ASSERT_TRUE(animation.center);
  expectVec(*animation.center, 1, 2, 3);
  EXPECT_DOUBLE_EQ(animation.degrees, 180);
}

TEST(SceneLoader, EmptySceneTakesEveryDefault) {
  const SceneDescription scene = parseScene("", "scene.toml");
  EXPECT_EQ(scene.path, "scene.toml");
  expectRender(scene.render, RenderSettings{.width = 800,
                                            .height = 600,
                                            .samples = 1,
                                            .maxDepth = 5,
                                            .sampler = SamplerKind::Regular,
                                            .shading = ShadingMode::Phong,
                                            .background = {0, 0, 0},
                                            .output = "",
                                            .srgb = true});
  EXPECT_EQ(scene.camera.projection, Projection::Perspective);
  EXPECT_FALSE(scene.camera.position);
  EXPECT_FALSE(scene.camera.lookAt);
  expectVec(scene.camera.up, 0, 1, 0);
  EXPECT_DOUBLE_EQ(scene.camera.fovDegrees, 40);
  EXPECT_FALSE(scene.camera.viewHeight);
  expectVec(scene.ambient, 0.1f, 0.1f, 0.1f);
  EXPECT_TRUE(scene.lights.empty());
  ASSERT_EQ(scene.materials.size(), 1u);
  expectDefaultMaterial(scene.materials[0]);
  EXPECT_TRUE(scene.meshes.empty());
  EXPECT_FALSE(scene.animation);
}

TEST(SceneLoader, UpAxisTurnsTheAutomaticCameraAndTheTurntable) {
  const SceneDescription scene = parseScene("[camera]\nup_axis = \"z\"\n[animation]\n", "scene.toml");
  expectVec(scene.camera.up, 0, 0, 1);
  // The 3/4 view from the right, above (+z) and in front (-y).
  expectVec(scene.camera.viewFrom, 0.9, -1.3, 0.65);
  EXPECT_FALSE(scene.animation->axis);  // the orbit takes the camera's up
  expectVec(parseScene("[camera]\n", "scene.toml").camera.viewFrom, 0.9, 0.65, 1.3);
}

TEST(SceneLoader, AnimationTableTakesDefaultsForAbsentKeys) {
  const SceneDescription scene = parseScene("[animation]\n", "scene.toml");
  ASSERT_TRUE(scene.animation);
  EXPECT_EQ(scene.animation->frames, 36);
  EXPECT_DOUBLE_EQ(scene.animation->fps, 12);
  EXPECT_EQ(scene.animation->orbitLight, -1);
  EXPECT_FALSE(scene.animation->axis);  // the camera's up, y by default
  expectVec(scene.camera.up, 0, 1, 0);
  EXPECT_FALSE(scene.animation->center);
  EXPECT_DOUBLE_EQ(scene.animation->degrees, 360);
  EXPECT_EQ(parseScene("[animation]\norbit = \"camera\"\n", "scene.toml").animation->orbitLight, -1);
}

TEST(SceneLoader, UserDefaultMaterialReplacesTheBuiltInOne) {
  const SceneDescription scene = parseScene(R"([material.red]
kd = [1, 0, 0]
[material.default]
kd = [0, 0, 1]
[[mesh]]
file = "a.msh"
)",
                                            "scene.toml");
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.materials[0].name, "default");
  expectVec(scene.materials[0].kd, 0, 0, 1);
  EXPECT_EQ(scene.materials[1].name, "red");
  EXPECT_EQ(scene.meshes[0].material, 0);
}

TEST(SceneLoader, PathsResolveAgainstTheSceneFolder) {
  const std::string text = "[render]\noutput = \"../out/a.png\"\n[[mesh]]\nfile = \"./meshes/b.msh\"\n";
  const SceneDescription nested = parseScene(text, "/data/scenes/demo.toml");
  EXPECT_EQ(nested.render.output, "/data/out/a.png");
  EXPECT_EQ(nested.meshes[0].file, "/data/scenes/meshes/b.msh");
  const SceneDescription here = parseScene(text, "demo.toml");
  EXPECT_EQ(here.render.output, "../out/a.png");
  EXPECT_EQ(here.meshes[0].file, "meshes/b.msh");
}

TEST(SceneLoader, IntegersAreAcceptedWhereNumbersAreExpected) {
  const SceneDescription scene = parseScene(R"([camera]
fov = 30
position = [1, 2, 3]
[material.m]
shininess = 7
ior = 2
)",
                                            "scene.toml");
  EXPECT_DOUBLE_EQ(scene.camera.fovDegrees, 30);
  expectVec(*scene.camera.position, 1, 2, 3);
  EXPECT_FLOAT_EQ(scene.materials[1].shininess, 7);
  EXPECT_FLOAT_EQ(scene.materials[1].ior, 2);
}

TEST(SceneLoader, TransparentBackground) {
  const SceneDescription scene = parseScene("[render]\nbackground = \"transparent\"\n", "scene.toml");
  EXPECT_TRUE(scene.render.transparentBackground);
  expectVec(scene.render.background, 0, 0, 0);
}

TEST(SceneLoader, AdaptiveSamplerAcceptsAnySampleBudget) {
  const SceneDescription scene = parseScene("[render]\nsamples = 8\nsampler = \"adaptive\"\n", "scene.toml");
  EXPECT_EQ(scene.render.sampler, SamplerKind::Adaptive);
  EXPECT_EQ(scene.render.samples, 8);
}

TEST(SceneLoader, GroupsMayBeWrittenAsASubTable) {
  const SceneDescription scene = parseScene(R"([material.matte]
[[mesh]]
file = "a.msh"
[mesh.groups]
Floor = "matte"
)",
                                            "scene.toml");
  ASSERT_EQ(scene.meshes[0].groupMaterials.size(), 1u);
  EXPECT_EQ(scene.meshes[0].groupMaterials[0].group, "Floor");
  EXPECT_EQ(scene.meshes[0].groupMaterials[0].material, 1);
}

TEST(SceneLoader, TopDownViewWithDefaultUpIsLeftToTheCamera) {
  // Only an explicit up along the line of sight is an error; the camera picks another up itself.
  const SceneDescription scene =
      parseScene("[camera]\nposition = [0, 5, 0]\nlook_at = [0, 0, 0]\n", "scene.toml");
  expectVec(scene.camera.up, 0, 1, 0);
}

TEST(SceneLoader, OrbitMayNameALightDefinedLaterInTheFile) {
  const SceneDescription scene = parseScene(
      "[animation]\norbit = \"light:1\"\n[[light]]\nposition = [0, 0, 0]\n[[light]]\nposition = [1, 0, 0]\n",
      "scene.toml");
  EXPECT_EQ(scene.animation->orbitLight, 1);
}

TEST(SceneLoader, ExampleScenesLoad) {
  for (const char* name : {"demo.toml", "sphere.toml", "technical_view.toml"}) {
    SCOPED_TRACE(name);
    const std::string path = std::string(LANCER_SOURCE_DIR "/examples/") + name;
    const SceneDescription scene = loadScene(path);
    EXPECT_FALSE(scene.meshes.empty());
  }
}

}  // namespace
}  // namespace lancer
