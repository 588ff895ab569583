// The scene keys of the optics and the adaptive sampler: a material that would reflect and transmit
// more than all the light it receives, and a non-positive adaptive threshold, are refused with the
// position of the offending key.
#include <gtest/gtest.h>

#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

using test::sceneErrorOf;

TEST(OpticsKeysBadInput, ReflectivityPlusTransparencyAboveOne) {
  EXPECT_EQ(
      sceneErrorOf("[material.glass]\nreflectivity = [0.1, 0.3, 0.2]\ntransparency = 0.8\n"),
      "scene.toml:3:16: error: material.glass: reflectivity + transparency must not exceed 1 in any channel "
      "(found 0.3 + 0.8): they share the light leaving the surface with the local colour; lower one of them");
  // Exactly 1 is allowed: a perfect glass with a coloured mirror share.
  EXPECT_EQ(sceneErrorOf("[material.glass]\nreflectivity = 0.25\ntransparency = 0.75\n"), "(no InputError)");
}

TEST(OpticsKeysBadInput, AdaptiveThresholdMustBePositive) {
  const std::string error = sceneErrorOf("[render]\nsampler = \"adaptive\"\nadaptive_threshold = 0\n");
  EXPECT_TRUE(error.starts_with("scene.toml:3:22: error: render.adaptive_threshold")) << error;
  EXPECT_EQ(sceneErrorOf("[render]\nsampler = \"adaptive\"\nsamples = 12\nadaptive_threshold = 0.02\n"),
            "(no InputError)");
}

TEST(OpticsKeysBadInput, OpticalMaterialKeysAreRead) {
  const SceneDescription scene = parseScene(
      "[render]\nadaptive_threshold = 0.125\n[material.g]\nreflectivity = [0.1, 0.2, 0.05]\ntransparency = "
      "0.7\n"
      "ior = 1.33\nfresnel = true\nabsorption = [0.5, 0.25, 0]\n",
      "scene.toml");
  EXPECT_FLOAT_EQ(scene.render.adaptiveThreshold, 0.125f);
  const Material& g = scene.materials.at(1);
  EXPECT_FLOAT_EQ(g.reflectivity.y, 0.2f);
  EXPECT_FLOAT_EQ(g.transparency, 0.7f);
  EXPECT_FLOAT_EQ(g.ior, 1.33f);
  EXPECT_TRUE(g.fresnel);
  EXPECT_FLOAT_EQ(g.absorption.y, 0.25f);
}

}  // namespace
}  // namespace lancer
