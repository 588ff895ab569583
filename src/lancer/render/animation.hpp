// Orbit animations: the camera or one light turns about an axis through the scene while the
// geometry and its accelerator stay as they are (built once, reused by every frame).
#pragma once

#include <functional>
#include <string>

#include "lancer/render/renderer.hpp"

namespace lancer {

// Angle of frame k: evenly spaced; a full turn (a multiple of 360 degrees) does not repeat its first
// frame at the end, a partial sweep ends exactly at `degrees`.
double orbitAngleDegrees(const AnimationSettings& animation, int frame);

// Rodrigues' rotation of p about the line through `center` along `axis` (any non-zero length).
Vec3d rotateAbout(const Vec3d& p, const Vec3d& center, const Vec3d& axis, double degrees);

// The orbit's axis: the animation's, else the camera's up (a turntable about the up axis).
Vec3d orbitAxis(const AnimationSettings& animation, const CameraSettings& camera);

// World-space centre of the orbit: the animation's, else the centre of the scene's bounds.
Vec3d orbitCenter(const AnimationSettings& animation, const Scene& scene);

// The camera of frame k of a camera orbit: position, look-at and up turned about the axis. A camera
// without a position starts from the default 3/4 view, as `lancer render` would place it.
CameraSettings orbitCamera(const CameraSettings& camera, const AnimationSettings& animation,
                           const Scene& scene, int imageWidth, int imageHeight, int frame);

// --orbit's (and lancer.animate's orbit=) value: -1 for "camera", K for "light:K" with K below
// lightCount. Throws InputError naming the choices otherwise.
int parseOrbit(const std::string& orbit, std::size_t lightCount);

struct AnimationProgress {
  int frame = 0;  // 0-based frame being rendered
  int frames = 0;
  RenderProgress frameProgress;
  double seconds = 0;  // since the animation started
};

struct AnimationStats {
  double seconds = 0;
  std::uint64_t rays = 0;
  bool cancelled = false;
};

// Frame `frame` alone, as renderAnimation renders it: a cluster job renders the frames it was given.
// `scene`'s lights are turned for the frame and restored before returning.
Image renderAnimationFrame(Scene& scene, const Accelerator& accelerator, const SceneDescription& description,
                           const AnimationSettings& animation, int frame, const RenderOptions& options,
                           RenderStats* stats = nullptr);

// Renders every frame in order with all threads (frames one after another: each frame is already
// parallel over tiles) and hands each finished frame to `onFrame`. `scene` is modified while a light
// orbits (or, with description.lightsFollowCamera, while the lights turn with the camera) and restored
// before returning.
AnimationStats renderAnimation(Scene& scene, const Accelerator& accelerator,
                               const SceneDescription& description, const AnimationSettings& animation,
                               const RenderOptions& options,
                               const std::function<void(int frame, const Image&)>& onFrame,
                               const std::function<void(const AnimationProgress&)>& onProgress = {});

}  // namespace lancer
