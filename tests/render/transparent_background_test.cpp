// Transparent backgrounds: alpha is the anti-aliased coverage, so a silhouette blends over any page.
#include <gtest/gtest.h>

#include <cmath>

#include "lancer/scene/scene_loader.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

TEST(TransparentBackground, AlphaIsTheCoveredFractionOfEachPixel) {
  for (SamplerKind sampler : {SamplerKind::Regular, SamplerKind::Stratified}) {
    for (int n : {2, 4, 8}) {
      // One world unit per pixel; pixel column 4 spans x in [0, 1].
      SceneDescription d = test::topDownView(8, 8, 8);
      d.render.samples = n * n;
      d.render.sampler = sampler;
      d.render.transparentBackground = true;
      d.lights = {{Vec3d{0, 0, 9}, {1, 1, 1}, {1, 0, 0}}};
      d.materials = {defaultMaterial()};
      d.meshes.resize(1);
      // Covers x < 0.3: column 4 is 30% covered, columns 0..3 fully, 5..7 not at all.
      const Image image = test::renderMeshes(d, {test::squareMesh(-10, -10, 0.3f, 10, 0)});
      double meanAlpha = 0;
      for (int y = 0; y < 8; ++y) {
        meanAlpha += image.at(4, y).a / 8.0;
        EXPECT_EQ(image.at(2, y).a, 1.0f);
        EXPECT_EQ(image.at(6, y).a, 0.0f);
      }
      EXPECT_NEAR(meanAlpha, 0.3, 1.0 / (2 * n)) << "n = " << n;
      EXPECT_TRUE(image.hasTransparency());
    }
  }
}

}  // namespace
}  // namespace lancer
