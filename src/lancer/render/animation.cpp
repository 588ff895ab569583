#include "lancer/render/animation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "lancer/util/stopwatch.hpp"

namespace lancer {

double orbitAngleDegrees(const AnimationSettings& animation, int frame) {
  const double turns = animation.degrees / 360.0;
  const bool fullTurn = animation.degrees != 0 && std::abs(turns - std::round(turns)) < 1e-12;
  const int steps = fullTurn ? animation.frames : std::max(animation.frames - 1, 1);
  return animation.degrees * static_cast<double>(frame) / static_cast<double>(steps);
}

Vec3d rotateAbout(const Vec3d& p, const Vec3d& center, const Vec3d& axis, double degrees) {
  // (p - center) + center is not always p in floating point: frame 0 must be the unmoved scene, bit for bit.
  if (degrees == 0) return p;
  const Vec3d k = normalize(axis);
  const Vec3d v = p - center;
  const double angle = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  return center + v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

Vec3d orbitAxis(const AnimationSettings& animation, const CameraSettings& camera) {
  return animation.axis.value_or(camera.up);
}

Vec3d orbitCenter(const AnimationSettings& animation, const Scene& scene) {
  if (animation.center) return *animation.center;
  return scene.geometry.origin +
         toDouble(scene.geometry.bounds.empty() ? Vec3{} : scene.geometry.bounds.center());
}

CameraSettings orbitCamera(const CameraSettings& givenCamera, const AnimationSettings& animation,
                           const Scene& scene, int imageWidth, int imageHeight, int frame) {
  const Aabbd worldBounds{scene.geometry.origin + toDouble(scene.geometry.bounds.lower),
                          scene.geometry.origin + toDouble(scene.geometry.bounds.upper)};
  const double aspect = static_cast<double>(imageWidth) / imageHeight;
  // The first frame's camera, placed whole (the automatic one's window too), then turned.
  const CameraSettings camera =
      placeAutomaticCamera(resolveGmshView(givenCamera, worldBounds, aspect), worldBounds, aspect);
  CameraSettings result = camera;
  const Vec3d position = *camera.position;
  const Vec3d lookAt = *camera.lookAt;
  const Vec3d centre = orbitCenter(animation, scene);
  const Vec3d axis = orbitAxis(animation, camera);
  const double degrees = orbitAngleDegrees(animation, frame);
  result.position = rotateAbout(position, centre, axis, degrees);
  result.lookAt = rotateAbout(lookAt, centre, axis, degrees);
  result.up = rotateAbout(camera.up, Vec3d{}, axis, degrees);
  return result;
}

int parseOrbit(const std::string& orbit, std::size_t lightCount) {
  if (orbit == "camera") return -1;
  // "light:K" with K plain decimal digits, as the scene file's animation.orbit accepts.
  const std::string digits = orbit.rfind("light:", 0) == 0 ? orbit.substr(6) : std::string();
  const bool number = !digits.empty() && digits.size() <= 9 &&
                      std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (number && static_cast<std::size_t>(std::stoi(digits)) < lightCount) return std::stoi(digits);
  if (lightCount == 0)
    throw InputError(
        SourceLocation{"--orbit"},
        fmt::format("'{}' is not an orbit here: the scene has no [[light]]; use 'camera'", orbit));
  throw InputError(
      SourceLocation{"--orbit"},
      fmt::format("'{}' is not an orbit: use 'camera' or 'light:K' with K from 0 to {} (the scene has "
                  "{} light{})",
                  orbit, lightCount - 1, lightCount, lightCount == 1 ? "" : "s"));
}

Image renderAnimationFrame(Scene& scene, const Accelerator& accelerator, const SceneDescription& description,
                           const AnimationSettings& animation, int frame, const RenderOptions& options,
                           RenderStats* stats) {
  const RenderSettings& settings = description.render;
  const bool lightOrbit = animation.orbitLight >= 0;
  // The lights that turn: the orbiting one, or (quick look) all of them with the camera.
  const bool lightsWithCamera = !lightOrbit && description.lightsFollowCamera;
  const std::vector<SceneLight> originalLights = scene.appearance.lights;
  // The scene's lights come back as they were however the frame ends (the render may throw).
  struct RestoreLights {
    Scene& scene;
    const std::vector<SceneLight>& lights;
    ~RestoreLights() { scene.appearance.lights = lights; }
  } restoreLights{scene, originalLights};
  const Vec3d centre = orbitCenter(animation, scene);
  const Vec3d axis = orbitAxis(animation, description.camera);
  auto turnLight = [&](std::size_t index, double degrees) {
    // Scene space and back is not exact, so an unturned light keeps its own coordinates.
    scene.appearance.lights[index] = originalLights[index];
    if (degrees == 0) return;
    SceneLight& light = scene.appearance.lights[index];
    light.position = scene.geometry.toSceneSpace(
        rotateAbout(scene.geometry.origin + toDouble(originalLights[index].position), centre, axis, degrees));
    // A sun's direction and a flat light's frame turn with it.
    auto turn = [&](const Vec3& v) { return toFloat(rotateAbout(toDouble(v), Vec3d{}, axis, degrees)); };
    light.direction = turn(light.direction);
    light.axisU = turn(light.axisU);
    light.axisV = turn(light.axisV);
  };
  CameraSettings cameraSettings = description.camera;
  const double degrees = orbitAngleDegrees(animation, frame);
  if (lightOrbit) {
    turnLight(static_cast<std::size_t>(animation.orbitLight), degrees);
  } else {
    cameraSettings =
        orbitCamera(description.camera, animation, scene, settings.width, settings.height, frame);
    if (lightsWithCamera)
      for (std::size_t i = 0; i < scene.appearance.lights.size(); ++i) turnLight(i, degrees);
  }
  const Camera camera = makeCamera(cameraSettings, scene, settings);
  return Renderer(scene, accelerator, camera, settings).renderFinal(options, stats);
}

AnimationStats renderAnimation(Scene& scene, const Accelerator& accelerator,
                               const SceneDescription& description, const AnimationSettings& animation,
                               const RenderOptions& options,
                               const std::function<void(int frame, const Image&)>& onFrame,
                               const std::function<void(const AnimationProgress&)>& onProgress) {
  const Stopwatch stopwatch;
  AnimationStats stats;
  for (int frame = 0; frame < animation.frames; ++frame) {
    RenderOptions frameOptions = options;
    if (onProgress) {
      frameOptions.onProgress = [&](const RenderProgress& progress) {
        AnimationProgress p;
        p.frame = frame;
        p.frames = animation.frames;
        p.frameProgress = progress;
        p.seconds = stopwatch.seconds();
        onProgress(p);
      };
    }
    RenderStats frameStats;
    const Image image =
        renderAnimationFrame(scene, accelerator, description, animation, frame, frameOptions, &frameStats);
    stats.rays += frameStats.rays;
    if (frameStats.cancelled || (options.cancel != nullptr && options.cancel->load())) {
      stats.cancelled = true;
      break;
    }
    onFrame(frame, image);
  }
  stats.seconds = stopwatch.seconds();
  return stats;
}

}  // namespace lancer
