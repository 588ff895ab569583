// Whitted-style recursive ray tracing over a Scene and its accelerator: nearest hit, the local
// lighting model with shadow rays, then mirror reflection and refraction up to a depth.
#pragma once

#include <span>

#include "lancer/accel/accelerator.hpp"
#include "lancer/accel/ray_packet.hpp"
#include "lancer/render/camera.hpp"
#include "lancer/render/edge_paint.hpp"
#include "lancer/render/integrator.hpp"
#include "lancer/render/scene_queries.hpp"
#include "lancer/render/surface_point.hpp"
#include "lancer/scene/scene.hpp"

namespace lancer {

struct PrimaryAhead;  // primary_ahead.hpp: what a packet traced ahead for one primary ray

// Where one ray of the Whitted ray tree stands, passed down the tree.
struct RayPath {
  int depth = 0;
  float weight = 1;           // the ray's weight in the pixel
  float length = 0;           // how far its origin is from the eye along the path, for edge widths
  bool parallelView = false;  // an orthographic primary ray: the viewer is at infinity along it
  TraceCounters* counters = nullptr;
  const PrimaryAhead* ahead = nullptr;  // the primary ray's queries, traced ahead in a packet
};

// EnergySplit, energySplit, MediumCrossing: scene_queries.hpp.
class Tracer {
 public:
  // `footprint`: the world size of a pixel along primary rays, for edges drawn in pixel widths.
  Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
         PixelFootprint footprint = {});
  // For primary rays of `camera` (which must outlive the tracer): edges get its pixel footprint,
  // and edges on outlines are drawn whole (outline_edges.hpp).
  Tracer(const Scene& scene, const Accelerator& accelerator, const RenderSettings& settings,
         const Camera& camera);

  // The integrator's answer (integrator.hpp): tracePrimary for the camera's projection. The Whitted
  // model draws no random numbers, and traces camera rays as packets (tracePrimaries).
  static constexpr bool kDeterministic = true;
  TraceResult li(const Ray& ray, SampleStream& /*samples*/, TraceCounters& counters) const {
    return tracePrimary(ray, parallelView_, counters);
  }
  void liPacket(std::span<const Ray, kPacketSize> rays, std::uint32_t active,
                std::span<TraceResult, kPacketSize> results, TraceCounters& counters) const {
    tracePrimaries(rays, active, parallelView_, results, counters);
  }
  // `parallelView`: the ray is an orthographic primary ray, so the viewer is at infinity along it.
  TraceResult tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters) const;
  // The primary rays of lanes `active` (up to kPacketSize neighbouring pixels or samples), each with
  // the result tracePrimary gives it, to the bit: their first hits and their shadow rays to each
  // light traced as packets (ray_packet.hpp, primary_ahead.hpp), then each shaded on its own.
  void tracePrimaries(std::span<const Ray, kPacketSize> rays, std::uint32_t active, bool parallelView,
                      std::span<TraceResult, kPacketSize> results, TraceCounters& counters) const;

  const SceneQueries& queries() const { return queries_; }

 private:
  // What a ray brings back: its colour, how far it went to the first thing it saw (infinity on a
  // miss: for absorption and edge widths), and how much of a pixel that thing covers (1 on geometry,
  // the shadow's density on a shadow catcher, 0 on a miss: the alpha of transparent backgrounds).
  struct TracedRay {
    Vec3 color;
    float distance;
    float coverage;
  };
  TracedRay trace(const Ray& ray, const RayPath& path) const;
  TraceResult tracePrimary(const Ray& ray, bool parallelView, TraceCounters& counters,
                           const PrimaryAhead* ahead) const;
  // The Whitted step at a surface hit `distance` along the ray: the local model, then the reflected
  // and transmitted branches.
  Vec3 shadeSurface(const Ray& ray, const Hit& hit, float distance, const RayPath& path) const;
  // One branch of the ray tree with its weight: traced (and absorbed by the medium it runs in) when
  // its path weight is worth it, else the point's local colour in its place. `path`: the parent's,
  // its length up to the branch's origin.
  template <typename MakeRay>
  Vec3 traceBranch(const Vec3& weight, const Vec3& absorption, const Vec3& local, MakeRay&& makeRay,
                   const RayPath& path) const;
  // The shadow-catcher floor at `point`: the background darkened by the meshes' shadows.
  Vec3 shadeShadowCatcher(const Vec3& point, TraceCounters& counters, float& coverage,
                          const PrimaryAhead* ahead) const;
  // The flat face a capped clip plane shows where it cuts a solid, at ray parameter `tCap`, in the
  // solid's `material` (`face`: the face the ray would leave the solid by, for field colours).
  Vec3 shadeCap(const Ray& ray, const ClipPlane& plane, float tCap, std::uint32_t face,
                std::uint32_t material, bool parallelView, TraceCounters& counters) const;
  Vec3 shadeLocal(const Ray& ray, const SurfacePoint& surface, const Material& material, bool parallelView,
                  TraceCounters& counters, const PrimaryAhead* ahead = nullptr) const;

  const Scene& scene_;
  SceneQueries queries_;
  EdgePaint paint_;
  Vec3 background_;
  int maxDepth_;
  bool linearFieldColors_ = false;  // --srgb: field colours are decoded to linear (field_shading.hpp)
  bool parallelView_ = false;       // the camera's, for li
};

}  // namespace lancer
