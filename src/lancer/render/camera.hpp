// Pinhole (perspective) and orthographic cameras: turn an image-plane position into a primary ray.
// Right-handed: looking down -z with up = +y puts +x on the image's right.
#pragma once

#include "lancer/math/aabb.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/render/edge_overlay.hpp"
#include "lancer/scene/camera_placement.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

class Camera {
 public:
  // Builds the camera in scene space; missing position/look_at/view_height frame `sceneBounds`.
  // `sceneOrigin` converts the settings' world coordinates to scene space.
  Camera(const CameraSettings& settings, const Vec3d& sceneOrigin, const Aabb& sceneBounds, int imageWidth,
         int imageHeight);

  // (x, y) in pixels from the image's top-left corner; pixel centres are at half-integers.
  Ray generateRay(float x, float y) const;
  // The same ray, made in place: returned by value into a packet, the ray was stored piecewise and
  // copied whole at once, a stalled store-to-load forward per ray (5% of examples/demo.toml).
  // Out of line on purpose: inlined into a caller's loop, the compiler fuses its products
  // differently there and primary rays (so images) change in the last bit.
  void generateRay(float x, float y, Ray& ray) const;

  Projection projection() const { return projection_; }
  // World size of one pixel along a primary ray: grows with distance for a perspective camera,
  // constant for an orthographic one.
  PixelFootprint pixelFootprint() const;
  // The inverse of generateRay: the image position (pixels from the top-left corner) where scene
  // point p appears; false when it is behind a perspective camera.
  bool project(const Vec3& p, float& x, float& y) const;
  const Vec3& position() const { return position_; }
  const Vec3& forward() const { return forward_; }

 private:
  Projection projection_;
  Vec3 position_;
  Vec3 forward_, right_, up_;     // unit, orthogonal
  float halfWidth_, halfHeight_;  // of the view window at distance 1 (perspective) or in world units
  float invWidth_, invHeight_;
  float shiftX_ = 0, shiftY_ = 0;  // perspective window off the axis (CameraSettings::shiftX, shiftY)
};

}  // namespace lancer
