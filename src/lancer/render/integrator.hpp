// What every integrator shares with the renderer: the result of one camera ray, the counters, and
// the concept an integrator satisfies (pbrt-v4's RayIntegrator::Li, Mitsuba's SamplingIntegrator).
#pragma once

#include <concepts>
#include <cstdint>
#include <span>

#include "lancer/accel/ray_packet.hpp"
#include "lancer/math/ray.hpp"
#include "lancer/math/vec3.hpp"
#include "lancer/render/feature_buffers.hpp"
#include "lancer/render/sample_sequence.hpp"

namespace lancer {

struct TraceResult {
  Vec3 color{0, 0, 0};
  float alpha = 0;  // 1 when the ray hit geometry (directly or through reflections), for coverage
};

struct TraceCounters {
  std::uint64_t rays = 0;  // primary + secondary + shadow
};

// An integrator answers one camera ray: the radiance it brings back (linear RGB, the units of
// docs/lighting.md) and the coverage of what it saw, drawing whatever random numbers it needs from
// the pixel's own sample stream (so the image is the same for any thread count and any split of
// the work). The integrators: the Whitted tracer (tracer.hpp, which ignores the stream), the path
// tracer (path_integrator.hpp) and ambient occlusion (ao_integrator.hpp). They share the surface
// records (surface_point.hpp), the scene queries (scene_queries.hpp), the lights and materials of
// the Scene and its accelerator. One pixel loop drives them all (pixel_loop.hpp); what it may do
// besides calling li, an integrator says with the capabilities below.
template <typename I>
concept RayIntegrator = requires(const I& integrator, const Ray& ray, SampleStream& samples,
                                 TraceCounters& counters) {
  { integrator.li(ray, samples, counters) } -> std::same_as<TraceResult>;
};

// An integrator that draws no random numbers (`static constexpr bool kDeterministic = true`): li
// ignores the stream, so its pixels are sampled at the points of the settings' sampler (the regular
// or stratified grid, or adaptive supersampling) rather than at the stream's, and `noise` does not
// apply. The others are Monte Carlo estimators, sampled at the points of their pixels' streams.
template <typename I>
concept DeterministicIntegrator = RayIntegrator<I> && requires {
  requires I::kDeterministic;
};

// A deterministic integrator that also traces up to kPacketSize camera rays at once (the lanes of
// `active`), each with the result li gives it, to the bit: the pixel loop then traces the camera
// rays of neighbouring pixels, or of neighbouring adaptive samples, as packets.
template <typename I>
concept PacketIntegrator = DeterministicIntegrator<I> &&
    requires(const I& integrator, std::span<const Ray, kPacketSize> rays, std::uint32_t active,
             std::span<TraceResult, kPacketSize> results, TraceCounters& counters) {
  integrator.liPacket(rays, active, results, counters);
};

// A Monte Carlo integrator that also says what its camera ray saw first (feature_buffers.hpp) from the
// same trace, with the same radiance and the same use of the stream as li: `first` receives the
// features of the first surface, or of the miss. The pixel loop then averages them over the pixel's
// own samples into the denoiser's buffers, and no separate feature pass is traced.
template <typename I>
concept FeatureIntegrator = RayIntegrator<I> &&
    requires(const I& integrator, const Ray& ray, SampleStream& samples, TraceCounters& counters,
             SurfaceFeatures* first) {
  { integrator.li(ray, samples, counters, first) } -> std::same_as<TraceResult>;
};

}  // namespace lancer
