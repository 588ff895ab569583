#include "lancer/render/adaptive_sampler.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "lancer/render/tracer.hpp"

namespace lancer {

int adaptiveMaxDepth(int samples) {
  int depth = 0;
  while (depth < kMaxAdaptiveDepth && (std::int64_t{1} << (2 * (depth + 1))) <= samples) ++depth;
  return depth;
}

template <DeterministicIntegrator Integrator>
AdaptiveSampler<Integrator>::AdaptiveSampler(const Integrator& integrator, const Camera& camera,
                                             const RenderSettings& settings, bool packets)
    : integrator_(integrator),
      camera_(camera),
      compareAlpha_(settings.transparentBackground),
      packets_(packets && PacketIntegrator<Integrator>),
      threshold_(settings.adaptiveThreshold),
      depth_(adaptiveMaxDepth(settings.samples)),
      side_((1 << depth_) + 1),
      lattice_(static_cast<std::size_t>(side_ * side_)),
      latticeStamp_(static_cast<std::size_t>(side_ * side_), 0) {}

template <DeterministicIntegrator Integrator>
typename AdaptiveSampler<Integrator>::Sample AdaptiveSampler<Integrator>::traceAt(
    float x, float y, TraceCounters& counters, std::uint64_t& samples) const {
  ++samples;
  SampleStream unused(0, 0, 0);  // a deterministic integrator draws nothing from it
  const TraceResult result = integrator_.li(camera_.generateRay(x, y), unused, counters);
  return {result.color, result.alpha};
}

template <DeterministicIntegrator Integrator>
bool AdaptiveSampler<Integrator>::differ(const Sample& a, const Sample& b, const Sample& c,
                                         const Sample& d) const {
  const Vec3 high = max(max(a.color, b.color), max(c.color, d.color));
  const Vec3 low = min(min(a.color, b.color), min(c.color, d.color));
  if (maxComponent(high - low) > threshold_) return true;
  return compareAlpha_ &&
         std::max({a.alpha, b.alpha, c.alpha, d.alpha}) - std::min({a.alpha, b.alpha, c.alpha, d.alpha}) >
             threshold_;
}

template <DeterministicIntegrator Integrator>
typename AdaptiveSampler<Integrator>::Sample& AdaptiveSampler<Integrator>::latticeSample(
    int i, int j, TraceCounters& counters, std::uint64_t& samples) {
  const auto index = static_cast<std::size_t>(j * side_ + i);
  if (latticeStamp_[index] != stamp_) {
    const float step = 1.0f / static_cast<float>(side_ - 1);
    lattice_[index] = traceAt(static_cast<float>(pixelX_) + static_cast<float>(i) * step,
                              static_cast<float>(pixelY_) + static_cast<float>(j) * step, counters, samples);
    latticeStamp_[index] = stamp_;
  }
  return lattice_[index];
}

template <DeterministicIntegrator Integrator>
typename AdaptiveSampler<Integrator>::Sample AdaptiveSampler<Integrator>::square(int i, int j, int size,
                                                                                 TraceCounters& counters,
                                                                                 std::uint64_t& samples) {
  const Sample a = latticeSample(i, j, counters, samples);
  const Sample b = latticeSample(i + size, j, counters, samples);
  const Sample c = latticeSample(i, j + size, counters, samples);
  const Sample d = latticeSample(i + size, j + size, counters, samples);
  if (size == 1 || !differ(a, b, c, d))
    return {(a.color + b.color + c.color + d.color) * 0.25f, (a.alpha + b.alpha + c.alpha + d.alpha) * 0.25f};
  const int half = size / 2;
  if (packets_) traceMidpoints(i, j, size, counters, samples);
  const Sample s00 = square(i, j, half, counters, samples);
  const Sample s10 = square(i + half, j, half, counters, samples);
  const Sample s01 = square(i, j + half, half, counters, samples);
  const Sample s11 = square(i + half, j + half, half, counters, samples);
  return {(s00.color + s10.color + s01.color + s11.color) * 0.25f,
          (s00.alpha + s10.alpha + s01.alpha + s11.alpha) * 0.25f};
}

template <DeterministicIntegrator Integrator>
void AdaptiveSampler<Integrator>::traceMidpoints(int i, int j, int size, TraceCounters& counters,
                                                 std::uint64_t& samples) {
  const int half = size / 2;
  const int points[5][2] = {
      {i + half, j}, {i, j + half}, {i + half, j + half}, {i + size, j + half}, {i + half, j + size}};
  const float step = 1.0f / static_cast<float>(side_ - 1);
  Ray rays[kPacketSize];
  std::size_t index[kPacketSize];
  std::uint32_t active = 0;
  for (int p = 0; p < 5; ++p) {
    index[p] = static_cast<std::size_t>(points[p][1] * side_ + points[p][0]);
    if (latticeStamp_[index[p]] == stamp_) continue;
    // The very ray latticeSample would trace there.
    camera_.generateRay(static_cast<float>(pixelX_) + static_cast<float>(points[p][0]) * step,
                        static_cast<float>(pixelY_) + static_cast<float>(points[p][1]) * step, rays[p]);
    active |= 1u << p;
  }
  if (std::popcount(active) < 2) return;  // one ray: latticeSample traces it as well
  TraceResult results[kPacketSize];
  if constexpr (PacketIntegrator<Integrator>) integrator_.liPacket(rays, active, results, counters);
  for (std::uint32_t lanes = active; lanes != 0; lanes &= lanes - 1) {
    const int p = std::countr_zero(lanes);
    ++samples;
    lattice_[index[p]] = {results[p].color, results[p].alpha};
    latticeStamp_[index[p]] = stamp_;
  }
}

template <DeterministicIntegrator Integrator>
Rgba AdaptiveSampler<Integrator>::shadePixel(int x, int y, const Sample corners[4], TraceCounters& counters,
                                             std::uint64_t& samples) {
  if (++stamp_ == 0) {  // wrapped: forget every stamp
    std::fill(latticeStamp_.begin(), latticeStamp_.end(), 0u);
    stamp_ = 1;
  }
  pixelX_ = x;
  pixelY_ = y;
  const int last = side_ - 1;
  const int cornerIndex[4][2] = {{0, 0}, {last, 0}, {0, last}, {last, last}};
  for (int c = 0; c < 4; ++c) {
    const auto index = static_cast<std::size_t>(cornerIndex[c][1] * side_ + cornerIndex[c][0]);
    lattice_[index] = corners[c];
    latticeStamp_[index] = stamp_;
  }
  const Sample value = square(0, 0, last, counters, samples);
  return toRgba(value.color, compareAlpha_ ? value.alpha : 1.0f);
}

template <DeterministicIntegrator Integrator>
void AdaptiveSampler<Integrator>::renderTile(int x0, int y0, int x1, int y1, Image& band, int bandY0,
                                             TraceCounters& counters, std::uint64_t& samples) {
  const int columns = x1 - x0 + 1, rows = y1 - y0 + 1;
  cornerRows_.resize(static_cast<std::size_t>(columns * rows));
  traceCorners(x0, y0, columns, rows, counters, samples);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const auto at = [&](int i, int j) { return cornerRows_[static_cast<std::size_t>(j * columns + i)]; };
      const int i = x - x0, j = y - y0;
      const Sample corners[4] = {at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)};
      band.at(x, y - bandY0) = shadePixel(x, y, corners, counters, samples);
    }
  }
}

template <DeterministicIntegrator Integrator>
void AdaptiveSampler<Integrator>::traceCorners(int x0, int y0, int columns, int rows, TraceCounters& counters,
                                               std::uint64_t& samples) {
  if (!packets_) {
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < columns; ++i)
        cornerRows_[static_cast<std::size_t>(j * columns + i)] =
            traceAt(static_cast<float>(x0 + i), static_cast<float>(y0 + j), counters, samples);
    return;
  }
  // Blocks of 4x2 corners, each one packet.
  constexpr int kBlockWidth = 4;
  Ray rays[kPacketSize];
  TraceResult results[kPacketSize];
  for (int j0 = 0; j0 < rows; j0 += 2) {
    for (int i0 = 0; i0 < columns; i0 += kBlockWidth) {
      std::uint32_t active = 0;
      for (int p = 0; p < kPacketSize; ++p) {
        const int i = i0 + p % kBlockWidth, j = j0 + p / kBlockWidth;
        if (i >= columns || j >= rows) continue;
        camera_.generateRay(static_cast<float>(x0 + i), static_cast<float>(y0 + j), rays[p]);
        active |= 1u << p;
      }
      if constexpr (PacketIntegrator<Integrator>) integrator_.liPacket(rays, active, results, counters);
      for (int p = 0; p < kPacketSize; ++p) {
        if ((active >> p & 1u) == 0) continue;
        ++samples;
        const int i = i0 + p % kBlockWidth, j = j0 + p / kBlockWidth;
        cornerRows_[static_cast<std::size_t>(j * columns + i)] = {results[p].color, results[p].alpha};
      }
    }
  }
}

template <DeterministicIntegrator Integrator>
Rgba AdaptiveSampler<Integrator>::renderPixel(int x, int y, TraceCounters& counters, std::uint64_t& samples) {
  Sample corners[4];
  for (int c = 0; c < 4; ++c)
    corners[c] =
        traceAt(static_cast<float>(x + (c & 1)), static_cast<float>(y + (c >> 1)), counters, samples);
  return shadePixel(x, y, corners, counters, samples);
}

template class AdaptiveSampler<Tracer>;

}  // namespace lancer
