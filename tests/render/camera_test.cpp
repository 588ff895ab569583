#include "lancer/render/camera.hpp"

#include <gtest/gtest.h>

namespace lancer {
namespace {

Aabb unitBox() { return Aabb{{-1, -1, -1}, {1, 1, 1}}; }

TEST(Camera, PerspectiveCentreRayLooksAtTarget) {
  CameraSettings settings;
  settings.position = Vec3d{0, 0, 5};
  settings.lookAt = Vec3d{0, 0, 0};
  const Camera camera(settings, {}, unitBox(), 200, 100);
  const Ray ray = camera.generateRay(100, 50);
  EXPECT_NEAR(ray.direction.x, 0, 1e-6);
  EXPECT_NEAR(ray.direction.y, 0, 1e-6);
  EXPECT_NEAR(ray.direction.z, -1, 1e-6);
  EXPECT_FLOAT_EQ(ray.origin.z, 5);
}

TEST(Camera, RightHandedImageAxes) {
  // Looking down -z with +y up: +x is image-right, +y is image-up.
  CameraSettings settings;
  settings.position = Vec3d{0, 0, 5};
  settings.lookAt = Vec3d{0, 0, 0};
  const Camera camera(settings, {}, unitBox(), 100, 100);
  EXPECT_GT(camera.generateRay(99, 50).direction.x, 0);
  EXPECT_LT(camera.generateRay(1, 50).direction.x, 0);
  EXPECT_GT(camera.generateRay(50, 1).direction.y, 0);
}

TEST(Camera, VerticalFieldOfViewSpansImageHeight) {
  CameraSettings settings;
  settings.position = Vec3d{0, 0, 0};
  settings.lookAt = Vec3d{0, 0, -1};
  settings.fovDegrees = 90;
  const Camera camera(settings, {}, unitBox(), 300, 100);
  const Ray top = camera.generateRay(150, 0);  // top edge: 45 degrees up
  EXPECT_NEAR(top.direction.y / -top.direction.z, 1.0, 1e-5);
  const Ray right = camera.generateRay(300, 50);  // right edge: aspect 3 times wider
  EXPECT_NEAR(right.direction.x / -right.direction.z, 3.0, 1e-5);
}

TEST(Camera, OrthographicRaysAreParallelAndSpanViewHeight) {
  CameraSettings settings;
  settings.projection = Projection::Orthographic;
  settings.position = Vec3d{0, 0, 10};
  settings.lookAt = Vec3d{0, 0, 0};
  settings.viewHeight = 4;
  const Camera camera(settings, {}, unitBox(), 200, 100);
  const Ray a = camera.generateRay(0, 0), b = camera.generateRay(200, 100);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_NEAR(a.origin.y - b.origin.y, 4.0, 1e-5);
  EXPECT_NEAR(b.origin.x - a.origin.x, 8.0, 1e-5);
}

TEST(Camera, SceneOriginIsSubtracted) {
  // A part at x = 1e6: the camera works in scene space, relative to the scene origin.
  CameraSettings settings;
  settings.position = Vec3d{1e6, 0, 5};
  settings.lookAt = Vec3d{1e6, 0, 0};
  const Camera camera(settings, Vec3d{1e6, 0, 0}, unitBox(), 100, 100);
  EXPECT_FLOAT_EQ(camera.position().x, 0);
  EXPECT_FLOAT_EQ(camera.position().z, 5);
}

TEST(Camera, DefaultPositionFramesTheBounds) {
  CameraSettings settings;  // no position: the 3/4 view
  const Camera camera(settings, {}, unitBox(), 100, 100);
  // The box centre is straight ahead and all 8 corners are inside the field of view.
  EXPECT_NEAR(dot(normalize(-camera.position()), camera.forward()), 1.0, 1e-5);
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{corner & 1 ? 1.f : -1.f, corner & 2 ? 1.f : -1.f, corner & 4 ? 1.f : -1.f};
    const Vec3 toCorner = normalize(p - camera.position());
    EXPECT_GT(dot(toCorner, camera.forward()), std::cos(20.0 * 3.14159265 / 180.0));
  }
}

}  // namespace
}  // namespace lancer
