// Unidirectional path tracing (Kajiya 1986; pbrt-v4's PathIntegrator): from each camera ray, a
// random walk through the scene that at every non-specular vertex estimates the direct light by
// next-event estimation (one sample per light, one of the environment map), weighted against the
// material's own sampling by the power heuristic (Veach & Guibas 1995) for lights with area and
// the map; Russian roulette after the third bounce; at most `max_bounces` scattering events.
//
// Units and estimators (docs/lighting.md): the pixel is the mean over its samples of the radiance
// L along a camera ray through a uniformly (Owen-scrambled Sobol') chosen point of the pixel (a box
// filter). A point or sun light of intensity I gives a Lambertian face of albedo kd exactly the
// Whitted model's diffuse term kd I cos(theta) (light_sampling.hpp); a uniform environment of
// radiance L gives kd L on a face nothing occludes. [ambient] and ka are not used: the
// environment is the light from all around. Materials: bsdf.hpp. Faces of a material with
// `emission` are lamps, sampled like the lights with area (emissive_faces.hpp). The shadow catcher, seen by
// camera rays, shows the miss colour darkened by the ratio of the irradiance it gets with and without the
// meshes in the way; rays past the first do not see it.
#pragma once

#include "lancer/accel/accelerator.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/edge_paint.hpp"
#include "lancer/render/emissive_faces.hpp"
#include "lancer/render/environment_light.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/render/scene_queries.hpp"
#include "lancer/render/surface_point.hpp"

namespace lancer {

struct LocalBsdf;
struct Sighting;

class PathIntegrator {
 public:
  // `camera` must outlive the integrator (outline edges).
  PathIntegrator(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
                 const Camera& camera);

  // With `first`, also what the camera ray sees first (FeatureIntegrator, integrator.hpp): the albedo
  // the radiance was multiplied by there (the field colour, isolines and edges painted on it), the
  // shading normal and the distance; a miss or the shadow catcher counts the background as albedo.
  TraceResult li(const Ray& ray, SampleStream& samples, TraceCounters& counters,
                 SurfaceFeatures* first = nullptr) const;

 private:
  // What a camera ray that meets nothing shows: the background, or the environment when visible.
  Vec3 missColor(const Vec3& direction) const;
  // Light arriving along a ray that left the scene: lights with area it points at and the
  // environment, MIS-weighted against `bsdfPdf` (0: a delta lobe or the camera chose it).
  Vec3 escaped(const Vec3& origin, const Vec3& direction, float bsdfPdf) const;
  // Next-event estimation at a point for the local lobe, whose chance of being sampled is
  // `lobeChance` (for the MIS weights): radiance towards the viewer over the lobe's weight.
  Vec3 directLight(const SurfacePoint& surface, const Vec3& shadowOrigin, const LocalBsdf& bsdf,
                   float lobeChance, SampleStream& samples, TraceCounters& counters) const;
  // The shadow catcher seen at `point` by a camera ray along `direction`.
  Vec3 shadeShadowCatcher(const Vec3& point, const Vec3& direction, SampleStream& samples,
                          TraceCounters& counters, float& coverage) const;

  const Scene& scene_;
  SceneQueries queries_;
  EdgePaint paint_;
  EmissiveFaces emissive_;
  EnvironmentLight environment_;
  Vec3 background_;
  int maxBounces_;
  float sceneSize_;
  bool linearFieldColors_;
};

}  // namespace lancer
