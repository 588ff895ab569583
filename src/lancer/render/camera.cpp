#include "lancer/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {
namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

}  // namespace

Camera::Camera(const CameraSettings& givenSettings, const Vec3d& sceneOrigin, const Aabb& sceneBounds,
               int imageWidth, int imageHeight)
    : projection_(givenSettings.projection) {
  const double aspect = static_cast<double>(imageWidth) / imageHeight;
  const Aabbd worldBounds{sceneOrigin + toDouble(sceneBounds.lower),
                          sceneOrigin + toDouble(sceneBounds.upper)};
  const CameraSettings settings =
      placeAutomaticCamera(resolveGmshView(givenSettings, worldBounds, aspect), worldBounds, aspect);
  projection_ = settings.projection;
  const Vec3d lookAt = *settings.lookAt;
  const Vec3d position = *settings.position;

  const Vec3d forward = normalize(lookAt - position);
  Vec3d right = normalize(cross(forward, settings.up));
  if (!(dot(right, right) > 0.5))
    right = normalize(cross(forward, std::abs(forward.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0}));
  const Vec3d up = cross(right, forward);
  position_ = toFloat(position - sceneOrigin);
  forward_ = toFloat(forward);
  right_ = toFloat(right);
  up_ = toFloat(up);

  if (projection_ == Projection::Perspective) {
    halfHeight_ = static_cast<float>(std::tan(0.5 * settings.fovDegrees * kDegrees));
  } else {
    // Default window: the bounding sphere's diameter with a margin, so the whole scene is in view.
    const double radius = std::max(0.5 * length(worldBounds.extent()), 1e-12);
    const double height = settings.viewHeight.value_or(2.16 * radius / std::min(1.0, aspect));
    halfHeight_ = static_cast<float>(0.5 * height);
  }
  halfWidth_ = static_cast<float>(halfHeight_ * aspect);
  shiftX_ = static_cast<float>(settings.shiftX);
  shiftY_ = static_cast<float>(settings.shiftY);
  invWidth_ = 1.0f / static_cast<float>(imageWidth);
  invHeight_ = 1.0f / static_cast<float>(imageHeight);
}

Ray Camera::generateRay(float x, float y) const {
  Ray ray;
  generateRay(x, y, ray);
  return ray;
}

void Camera::generateRay(float x, float y, Ray& ray) const {
  const float sx = (2.0f * x * invWidth_ - 1.0f) * halfWidth_ + shiftX_;
  const float sy = (1.0f - 2.0f * y * invHeight_) * halfHeight_ + shiftY_;
  if (projection_ == Projection::Perspective) {
    ray = Ray(position_, normalize(forward_ + right_ * sx + up_ * sy));
  } else {
    ray = Ray(position_ + right_ * sx + up_ * sy, forward_);
  }
}

bool Camera::project(const Vec3& p, float& x, float& y) const {
  const Vec3 v = p - position_;
  float sx = dot(v, right_), sy = dot(v, up_);
  if (projection_ == Projection::Perspective) {
    const float depth = dot(v, forward_);
    if (!(depth > 0.0f)) return false;
    sx = sx / depth - shiftX_;
    sy = sy / depth - shiftY_;
  } else {
    sx -= shiftX_;
    sy -= shiftY_;
  }
  x = 0.5f * (sx / halfWidth_ + 1.0f) / invWidth_;
  y = 0.5f * (1.0f - sy / halfHeight_) / invHeight_;
  return true;
}

PixelFootprint Camera::pixelFootprint() const {
  const float pixel = 2.0f * halfHeight_ * invHeight_;
  return projection_ == Projection::Perspective ? PixelFootprint{0.0f, pixel} : PixelFootprint{pixel, 0.0f};
}

}  // namespace lancer
