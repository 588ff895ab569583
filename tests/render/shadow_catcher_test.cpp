// The shadow-catcher floor: never drawn itself, it darkens the background by exactly the share of
// light the meshes take away, and over a transparent background the shadow becomes opacity.
#include <gtest/gtest.h>

#include "lancer/scene/scene_loader.hpp"
#include "support/input_errors.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// A 1 x 1 occluder at z = 1 over a catcher floor at z = 0, a light straight above at z = 10, seen
// from above; the occluder's shadow is |x|, |y| < 0.5 * 10 / 9.
SceneDescription occluderOverCatcher() {
  SceneDescription d = test::topDownView(40, 40, 2);
  d.render.shading = ShadingMode::Flat;
  d.render.background = {0.8f, 0.6f, 0.4f};
  d.ambient = {0.25f, 0.25f, 0.25f};
  d.lights = {{Vec3d{0, 0, 10}, {0.75f, 0.75f, 0.75f}, {1, 0, 0}}};
  d.materials = {defaultMaterial()};
  d.meshes.resize(1);
  d.floor = FloorSettings{0.0, Vec3d{0, 0, 1}};
  return d;
}

Image render(const SceneDescription& d) {
  return test::renderMeshes(d, {test::squareMesh(-0.5f, -0.5f, 0.5f, 0.5f, 1)});
}

TEST(ShadowCatcher, DarkensTheBackgroundByTheShareOfLightTakenAway) {
  const Image image = render(occluderOverCatcher());
  // Pixel (1, 20): x = -0.95, well outside the shadow: the background untouched.
  EXPECT_FLOAT_EQ(image.at(1, 20).r, 0.8f);
  EXPECT_FLOAT_EQ(image.at(1, 20).b, 0.4f);
  // Pixel (9, 20): x = -0.525, outside the occluder (0.5) but inside its shadow (0.556).
  const Rgba shadow = image.at(9, 20);
  // The floor point is 10 below the light at cos = 1 (to 2e-3): kept = 0.25 / (0.25 + 0.75 cos).
  const float kept = 0.25f / (0.25f + 0.75f);
  EXPECT_NEAR(shadow.r, 0.8f * kept, 2e-3f);
  EXPECT_NEAR(shadow.b, 0.4f * kept, 2e-3f);
  // The occluder itself is drawn as usual (not the background).
  EXPECT_GT(image.at(20, 20).r, 0.0f);
  EXPECT_NE(image.at(20, 20).r, 0.8f);
}

TEST(ShadowCatcher, OverATransparentBackgroundTheShadowIsOpacity) {
  SceneDescription d = occluderOverCatcher();
  d.render.transparentBackground = true;
  d.render.background = {0, 0, 0};
  const Image image = render(d);
  EXPECT_EQ(image.at(1, 20).a, 0.0f);                   // bare floor: transparent
  EXPECT_NEAR(image.at(9, 20).a, 1.0f - 0.25f, 2e-3f);  // shadow: 1 - kept
  EXPECT_EQ(image.at(20, 20).a, 1.0f);                  // the part: opaque
}

TEST(ShadowCatcher, DefaultHeightIsTheLowestPointAndKeysAreChecked) {
  SceneDescription d = occluderOverCatcher();
  d.floor->height.reset();  // the occluder's own plane z = 1: it casts no shadow on itself
  const Image image = render(d);
  EXPECT_FLOAT_EQ(image.at(9, 20).r, 0.8f);
  const SceneDescription parsed =
      parseScene("[floor]\nshadow_catcher = true\nheight = -2\nnormal = [0, 0, 3]\n", "f.toml");
  ASSERT_TRUE(parsed.floor.has_value());
  EXPECT_EQ(*parsed.floor->height, -2.0);
  EXPECT_EQ(parsed.floor->normal, (Vec3d{0, 0, 1}));
  EXPECT_EQ(test::sceneErrorOf("[floor]\nheight = 0\n", "f.toml"),
            "f.toml:1:1: error: [floor] has no 'shadow_catcher'; add shadow_catcher = true");
  test::expectSceneErrorContains("[floor]\nshadow_catcher = false\n",
                                 "f.toml:2:18: error: floor.shadow_catcher = false is not supported",
                                 "f.toml");
  test::expectSceneErrorContains("[floor]\nshadow_catcher = true\nnormal = [0, 0, 0]\n",
                                 "floor.normal must not be", "f.toml");
}

}  // namespace
}  // namespace lancer
