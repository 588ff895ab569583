// Field lines' tubes sized in pixels (`radius = "4px"`) are 4 pixels in the picture as it is framed:
// legends beside the model make the automatic camera frame it in a smaller part of the image, and a
// hidden skin makes it frame the tubes alone; the radius follows that camera, not the one that
// frames the meshes as read.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lancer/render/render_preparation.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

// The hexahedral cube (u = (1, 2, 3) at every node), its one field line through the centre sized 4
// pixels, seen square to the line (every point of it at the target's depth) with the line upright.
// The line stops 0.3 from the centre each way, its tube inside the cube: the picture frames the cube.
PreparedRender cubeWithLine(std::optional<LegendPlacement> legend, const std::string& skin = "edges") {
  RenderRequest request;
  request.description =
      parseScene("[[mesh]]\nfile = \"cube_hex.msh\"\nskin = \"" + skin +
                     "\"\n"
                     "streamlines = { field = \"u\", seed_points = [[0.5, 0.5, 0.5]], radius = \"4px\", "
                     "max_length = 0.3 }\n",
                 test::dataFile("volume/scene.toml"));
  request.description.camera.viewFrom = Vec3d{2, -1, 0};
  request.description.camera.up = normalize(Vec3d{1, 2, 3});
  request.overrides.width = 160;
  request.overrides.height = 120;
  request.overrides.legend = legend;
  return prepareRender(std::move(request));
}

// The tube's radius in pixels of the prepared picture: its radius in the model (the farthest of its
// vertices, those inside the cube, from the line: the skin's lie on the cube's faces), as long as it
// is drawn across the line at the line's depth.
double tubeRadiusInPixels(const PreparedRender& prepared) {
  const Scene& scene = prepared.scene;
  const Vec3d centre{0.5, 0.5, 0.5}, along = normalize(Vec3d{1, 2, 3});
  double radius = 0;
  for (const Vec3& p : scene.geometry.positions) {
    const Vec3d world = scene.geometry.origin + toDouble(p);
    if (std::min({world.x, world.y, world.z}) < 1e-3 || std::max({world.x, world.y, world.z}) > 1 - 1e-3)
      continue;
    const Vec3d off = world - centre;
    radius = std::max(radius, length(off - along * dot(off, along)));
  }
  const auto onScreen = [&](const Vec3d& world) {
    float x = 0, y = 0;
    EXPECT_TRUE(prepared.camera.project(scene.geometry.toSceneSpace(world), x, y));
    return Vec3d{x, y, 0};
  };
  const Vec3d across = normalize(cross(along, Vec3d{2, -1, 0}));  // square to the line and the view
  return length(onScreen(centre + across * radius) - onScreen(centre));
}

TEST(StreamlinePixelRadius, FourPixelsWithAndWithoutLegends) {
  const PreparedRender plain = cubeWithLine(std::nullopt);
  EXPECT_EQ(plain.description.camera.legendShareRight, 0.0);
  EXPECT_NEAR(tubeRadiusInPixels(plain), 4.0, 0.05);
  for (const LegendPlacement placement : {LegendPlacement::Right, LegendPlacement::Bottom}) {
    const PreparedRender beside = cubeWithLine(placement);
    // The legends took their side: the model is framed smaller, the tube still 4 pixels.
    EXPECT_GT(beside.description.camera.legendShareRight + beside.description.camera.legendShareBottom, 0.1);
    EXPECT_NEAR(tubeRadiusInPixels(beside), 4.0, 0.05);
  }
}

TEST(StreamlinePixelRadius, FourPixelsOfThePictureTheTubesAreFramedIn) {
  // The skin hidden, the picture frames the line alone, not the cube the meshes as read span: its
  // pixel is the one the tube is sized in (its bounds, the tube's own radius included, frame it).
  for (const std::optional<LegendPlacement> legend :
       {std::optional<LegendPlacement>(), std::optional(LegendPlacement::Right)}) {
    const PreparedRender alone = cubeWithLine(legend, "hidden");
    const Aabb& bounds = alone.scene.geometry.bounds;
    EXPECT_LT(length(toDouble(bounds.extent())), 1.0);  // the line's 0.6, not the cube's 1.7
    EXPECT_NEAR(tubeRadiusInPixels(alone), 4.0, 0.05);
  }
}

}  // namespace
}  // namespace lancer
