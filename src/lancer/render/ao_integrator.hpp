// Ambient occlusion (Zhukov, Iones & Kronin 1998): the share V of the hemisphere above a point
// that no geometry closer than `ao_distance` hides, estimated by one cosine-weighted direction per
// sample. A face shows kd L V, L the environment's radiance in that direction (1 without an
// [environment]): a white furnace of radiance L lit by one bounce, without the lights. The shadow
// catcher shows the miss colour darkened by V. Edges, caps and field colours as in the other modes.
#pragma once

#include "lancer/accel/accelerator.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/edge_paint.hpp"
#include "lancer/render/environment_light.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/render/scene_queries.hpp"

namespace lancer {

class AoIntegrator {
 public:
  AoIntegrator(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
               const Camera& camera);

  TraceResult li(const Ray& cameraRay, SampleStream& samples, TraceCounters& counters) const;

 private:
  // 1 when the cosine-weighted direction from (u, v) about `normal` is open up to the distance.
  float openness(const Vec3& from, const Vec3& direction, TraceCounters& counters) const;

  const Scene& scene_;
  SceneQueries queries_;
  EdgePaint paint_;
  EnvironmentLight environment_;
  Vec3 background_;
  float distance_;
  bool linearFieldColors_;
};

}  // namespace lancer
