#include "lancer/render/denoiser.hpp"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "lancer/util/parallel_for.hpp"

namespace lancer {
namespace {

// Below this an albedo channel is not divided out (black paint, a black background).
constexpr float kMinAlbedo = 0.01f;
// The B3-spline taps of the à-trous transform (Dammertz et al., section 3).
constexpr float kKernel[5] = {1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16};

// The guide of one pixel, ready for the weights.
struct Guide {
  Vec3 normal;  // unit, or zero where the pixel saw nothing
  Vec3 albedo;
  float depth;      // +infinity where nothing was hit
  float gradientX;  // |d depth / dx|, |d depth / dy| in world units per pixel (0 on a miss)
  float gradientY;
};

std::vector<Guide> makeGuides(const FeatureBuffers& f, int threads) {
  std::vector<Guide> guides(f.albedo.size());
  const auto depthAt = [&](int x, int y) { return f.depth[f.index(x, y)]; };
  // One-sided where a neighbour is missing or off the image: the slope of the surface itself.
  const auto slope = [](float before, float here, float after) {
    const bool b = std::isfinite(before), a = std::isfinite(after);
    if (a && b)
      return 0.5f * std::min(std::abs(after - here) + std::abs(here - before),
                             2.0f * std::min(std::abs(after - here), std::abs(here - before)));
    if (a) return std::abs(after - here);
    if (b) return std::abs(here - before);
    return 0.0f;
  };
  constexpr float kInf = std::numeric_limits<float>::infinity();
  parallelFor(static_cast<std::size_t>(f.height), threads, 16, [&](std::size_t row) {
    const int y = static_cast<int>(row);
    for (int x = 0; x < f.width; ++x) {
      const std::size_t k = f.index(x, y);
      Guide& g = guides[k];
      const float n = length(f.normal[k]);
      g.normal = n > 1e-6f ? f.normal[k] * (1.0f / n) : Vec3{0, 0, 0};
      g.albedo = f.albedo[k];
      g.depth = f.depth[k];
      g.gradientX = g.gradientY = 0;
      if (!std::isfinite(g.depth)) continue;
      g.gradientX =
          slope(x > 0 ? depthAt(x - 1, y) : kInf, g.depth, x + 1 < f.width ? depthAt(x + 1, y) : kInf);
      g.gradientY =
          slope(y > 0 ? depthAt(x, y - 1) : kInf, g.depth, y + 1 < f.height ? depthAt(x, y + 1) : kInf);
    }
  });
  return guides;
}

// Floats after the last pixel of every plane, so that a group of four lanes starting at any pixel
// reads inside it (filterRow).
constexpr std::size_t kPadding = 4;

// The guides as planes of floats, for the filter's loops over a row: the weights of one tap for a run
// of pixels are then the same arithmetic on consecutive values, which the compiler vectorises.
struct GuidePlanes {
  std::vector<float> nx, ny, nz, ax, ay, az;
  std::vector<float> depth;   // 0 on a miss
  std::vector<float> slopeX;  // depthSigma |d depth / dx|, 0 on a miss
  std::vector<float> slopeY;  // depthSigma |d depth / dy|
  std::vector<float> floor;   // 1e-4 depth: the depth difference always tolerated (0 on a miss)
  std::vector<float> hit;     // 1 where the pixel saw a surface, else 0
  float albedoScale;          // 1 / albedoSigma^2
  bool power128;              // normalPower is the default 128 (7 squarings)
  float normalPower;

  GuidePlanes(const std::vector<Guide>& guides, const DenoiseOptions& options)
      : albedoScale(1.0f / (options.albedoSigma * options.albedoSigma)),
        power128(options.normalPower == 128.0f),
        normalPower(options.normalPower) {
    for (std::vector<float>* plane : {&nx, &ny, &nz, &ax, &ay, &az, &depth, &slopeX, &slopeY, &floor, &hit})
      plane->resize(guides.size() + kPadding);
    for (std::size_t k = 0; k < guides.size(); ++k) {
      const Guide& g = guides[k];
      const bool seen = std::isfinite(g.depth);
      nx[k] = g.normal.x;
      ny[k] = g.normal.y;
      nz[k] = g.normal.z;
      ax[k] = g.albedo.x;
      ay[k] = g.albedo.y;
      az[k] = g.albedo.z;
      depth[k] = seen ? g.depth : 0.0f;
      slopeX[k] = seen ? options.depthSigma * g.gradientX : 0.0f;
      slopeY[k] = seen ? options.depthSigma * g.gradientY : 0.0f;
      floor[k] = seen ? 1e-4f * g.depth : 0.0f;
      hit[k] = seen ? 1.0f : 0.0f;
    }
  }
};

// Three planes of colour.
struct LightPlanes {
  std::vector<float> r, g, b;
  explicit LightPlanes(std::size_t size) : r(size + kPadding), g(r.size()), b(r.size()) {}
  explicit LightPlanes(const std::vector<Vec3>& values) : LightPlanes(values.size()) {
    for (std::size_t k = 0; k < values.size(); ++k) {
      r[k] = values[k].x;
      g[k] = values[k].y;
      b[k] = values[k].z;
    }
  }
  Vec3 at(std::size_t k) const { return {r[k], g[k], b[k]}; }
};

// The weighted sums of one row's pixels over the taps, reused row after row.
struct RowSums {
  std::vector<float> r, g, b, weight;
  explicit RowSums(int width)
      : r(static_cast<std::size_t>(width) + kPadding), g(r.size()), b(r.size()), weight(r.size()) {}
};

// e^-x for x >= 0 to about 2e-7 relative (2^(-x log2 e): the integer part into the exponent bits, a
// degree-5 polynomial for the fraction), 0 above 30 where a tap cannot move the sum. The library's
// expf, one call per tap, was a third of the filter's time; this one runs four lanes at once.
inline __m128 negativeExp(__m128 x) {
  const __m128 t = _mm_mul_ps(_mm_min_ps(x, _mm_set1_ps(30.0f)), _mm_set1_ps(-1.44269504f));  // [-43.3, 0]
  // floor(t): truncation, one less where that rounded a negative value up.
  __m128i whole = _mm_cvttps_epi32(t);
  whole = _mm_add_epi32(whole, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(whole), t)));  // -1 where true
  const __m128 f = _mm_sub_ps(t, _mm_cvtepi32_ps(whole));                                   // [0, 1)
  __m128 poly = _mm_set1_ps(0.00133335581f);  // 2^f: the minimax polynomial of degree 5 on [0, 1)
  for (const float c : {0.00961812911f, 0.0555041087f, 0.240226507f, 0.693147182f, 1.0f})
    poly = _mm_add_ps(_mm_mul_ps(poly, f), _mm_set1_ps(c));
  const __m128 scale = _mm_castsi128_ps(_mm_slli_epi32(_mm_add_epi32(whole, _mm_set1_epi32(127)), 23));
  return _mm_and_ps(_mm_mul_ps(poly, scale), _mm_cmple_ps(x, _mm_set1_ps(30.0f)));
}

// The planes' values of four consecutive pixels from k.
struct Lanes {
  const float* plane;
  __m128 at(std::ptrdiff_t k) const { return _mm_loadu_ps(plane + k); }
};

// One pass of the filter over row y into `out`: each pixel the weighted mean of its 5 x 5 taps at
// `step` pixels apart. A tap's weight: the B3 kernel, SVGF's w_n = max(0, n_p . n_q)^normalPower and
// w_z = exp(-|z_p - z_q| / (sigma_z |grad z_p . offset| + 1e-4 z_p)), a Gaussian in albedo and one in
// colour (at the centre's albedo, against the noise level); 0 across a silhouette against the
// background. Taps are taken row by row of the kernel, for four of the row's pixels at a time (SSE2,
// the x86-64 baseline); the normal power other than the default 128 takes a pow per lane.
void filterRow(int y, int width, int height, int step, float colorScale, const GuidePlanes& g,
               const LightPlanes& in, const LightPlanes& scale, const float* pixelScale, RowSums& sums,
               LightPlanes& out) {
  const float albedoScale = g.albedoScale, normalPower = g.normalPower;
  const bool power128 = g.power128;
  float* sumR = sums.r.data();
  float* sumG = sums.g.data();
  float* sumB = sums.b.data();
  float* sumW = sums.weight.data();
  std::fill(sumR, sumR + width + kPadding, 0.0f);
  std::fill(sumG, sumG + width + kPadding, 0.0f);
  std::fill(sumB, sumB + width + kPadding, 0.0f);
  std::fill(sumW, sumW + width + kPadding, 0.0f);
  const Lanes inR{in.r.data()}, inG{in.g.data()}, inB{in.b.data()};
  const Lanes scaleR{scale.r.data()}, scaleG{scale.g.data()}, scaleB{scale.b.data()};
  const Lanes ax{g.ax.data()}, ay{g.ay.data()}, az{g.az.data()}, nx{g.nx.data()}, ny{g.ny.data()},
      nz{g.nz.data()};
  const Lanes depth{g.depth.data()}, slopeX{g.slopeX.data()}, slopeY{g.slopeY.data()}, floor{g.floor.data()},
      hit{g.hit.data()};
  const __m128 signBits = _mm_set1_ps(-0.0f), zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(y) * width;
  for (int j = -2; j <= 2; ++j) {
    const int qy = y + j * step;
    if (qy < 0 || qy >= height) continue;
    const __m128 dy = _mm_set1_ps(static_cast<float>(std::abs(j * step)));
    for (int i = -2; i <= 2; ++i) {
      const int offset = i * step;
      const int x0 = std::max(0, -offset), x1 = std::min(width, width - offset);
      if (x0 >= x1) continue;
      const __m128 dx = _mm_set1_ps(static_cast<float>(std::abs(offset)));
      const __m128 kernel = _mm_set1_ps(kKernel[i + 2] * kKernel[j + 2]);
      const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(qy - y) * width + offset;
      // Four pixels at a time; the last group's lanes from x1 on read the next row or the planes'
      // padding (finite values) and get no weight.
      for (int start = x0; start < x1; start += 4) {
        const std::ptrdiff_t p = row + start, q = p + shift;
        const __m128 dr = _mm_mul_ps(_mm_sub_ps(inR.at(q), inR.at(p)), scaleR.at(p));
        const __m128 dg = _mm_mul_ps(_mm_sub_ps(inG.at(q), inG.at(p)), scaleG.at(p));
        const __m128 db = _mm_mul_ps(_mm_sub_ps(inB.at(q), inB.at(p)), scaleB.at(p));
        const __m128 dar = _mm_sub_ps(ax.at(p), ax.at(q)), dag = _mm_sub_ps(ay.at(p), ay.at(q)),
                     dab = _mm_sub_ps(az.at(p), az.at(q));
        const __m128 colour =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(dr, dr), _mm_mul_ps(dg, dg)), _mm_mul_ps(db, db));
        const __m128 albedo =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(dar, dar), _mm_mul_ps(dag, dag)), _mm_mul_ps(dab, dab));
        // Depth: on two misses both depths and the tolerance are 0; the max keeps 0 / 0 out.
        const __m128 expected = _mm_max_ps(
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(slopeX.at(p), dx), _mm_mul_ps(slopeY.at(p), dy)), floor.at(p)),
            _mm_set1_ps(1e-30f));
        const __m128 depthGap = _mm_andnot_ps(signBits, _mm_sub_ps(depth.at(p), depth.at(q)));
        const __m128 exponent = _mm_add_ps(
            _mm_add_ps(_mm_mul_ps(_mm_mul_ps(colour, _mm_loadu_ps(pixelScale + p)), _mm_set1_ps(colorScale)),
                       _mm_mul_ps(albedo, _mm_set1_ps(albedoScale))),
            _mm_div_ps(depthGap, expected));
        const __m128 cosine = _mm_max_ps(
            zero, _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx.at(p), nx.at(q)), _mm_mul_ps(ny.at(p), ny.at(q))),
                             _mm_mul_ps(nz.at(p), nz.at(q))));
        __m128 wn = cosine;
        if (power128) {
          for (int k = 0; k < 7; ++k) wn = _mm_mul_ps(wn, wn);
        } else {
          alignas(16) float lanes[4];
          _mm_store_ps(lanes, cosine);
          for (float& lane : lanes) lane = std::pow(lane, normalPower);
          wn = _mm_load_ps(lanes);
        }
        // hit is 0 or 1: w_n where both see a surface, 1 where both miss, 0 across a silhouette.
        const __m128 hp = hit.at(p), hq = hit.at(q);
        const __m128 same = _mm_sub_ps(one, _mm_andnot_ps(signBits, _mm_sub_ps(hp, hq)));
        const __m128 factor = _mm_mul_ps(same, _mm_add_ps(_mm_mul_ps(hp, wn), _mm_sub_ps(one, hp)));
        __m128 w = _mm_mul_ps(_mm_mul_ps(kernel, factor), negativeExp(exponent));
        if (x1 - start < 4) {
          const __m128i lane = _mm_set_epi32(3, 2, 1, 0);
          w = _mm_and_ps(w, _mm_castsi128_ps(_mm_cmplt_epi32(lane, _mm_set1_epi32(x1 - start))));
        }
        _mm_storeu_ps(sumR + start, _mm_add_ps(_mm_loadu_ps(sumR + start), _mm_mul_ps(inR.at(q), w)));
        _mm_storeu_ps(sumG + start, _mm_add_ps(_mm_loadu_ps(sumG + start), _mm_mul_ps(inG.at(q), w)));
        _mm_storeu_ps(sumB + start, _mm_add_ps(_mm_loadu_ps(sumB + start), _mm_mul_ps(inB.at(q), w)));
        _mm_storeu_ps(sumW + start, _mm_add_ps(_mm_loadu_ps(sumW + start), w));
      }
    }
  }
  for (int x = 0; x < width; ++x) {
    const std::ptrdiff_t p = row + x;
    const bool any = sumW[x] > 0.0f;
    out.r[static_cast<std::size_t>(p)] = any ? sumR[x] / sumW[x] : in.r[static_cast<std::size_t>(p)];
    out.g[static_cast<std::size_t>(p)] = any ? sumG[x] / sumW[x] : in.g[static_cast<std::size_t>(p)];
    out.b[static_cast<std::size_t>(p)] = any ? sumB[x] / sumW[x] : in.b[static_cast<std::size_t>(p)];
  }
}

// Pixels whose 2x2 block lies on one smooth surface: there the diagonal detail is noise alone.
bool smoothBlock(const Guide* g[4]) {
  for (int i = 1; i < 4; ++i) {
    if (std::isfinite(g[0]->depth) != std::isfinite(g[i]->depth)) return false;
    const Vec3 da = g[0]->albedo - g[i]->albedo;
    if (dot(da, da) > 1e-4f) return false;
    if (std::isfinite(g[0]->depth) && dot(g[0]->normal, g[i]->normal) < 0.99f) return false;
  }
  return true;
}

float estimateNoiseOf(const std::vector<Vec3>& light, const std::vector<Guide>& guides, int width,
                      int height) {
  std::vector<float> details;
  details.reserve(light.size());
  const auto at = [&](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x;
  };
  for (int y = 0; y + 1 < height; y += 2)
    for (int x = 0; x + 1 < width; x += 2) {
      const std::size_t k[4] = {at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y + 1)};
      const Guide* g[4] = {&guides[k[0]], &guides[k[1]], &guides[k[2]], &guides[k[3]]};
      if (!smoothBlock(g)) continue;
      // The finest diagonal Haar detail of each channel: a smooth gradient cancels, pixel noise of
      // deviation s leaves a detail of deviation s.
      const Vec3 d = (light[k[0]] - light[k[1]] - light[k[2]] + light[k[3]]) * 0.5f;
      // A block of exactly equal pixels has no noise to measure (the background, a floor the shadow
      // catcher sees unshadowed): where such blocks are most of the picture, counting them would put
      // the median at 0 and leave the rendered part as noisy as it came.
      if (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f) continue;
      details.insert(details.end(), {std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    }
  if (details.empty()) return 0.0f;
  const auto middle = details.begin() + static_cast<std::ptrdiff_t>(details.size() / 2);
  std::nth_element(details.begin(), middle, details.end());
  return *middle / 0.6745f;  // the median absolute deviation of a normal distribution
}

// The root mean of the pixels' own variances where their samples spread (0 where none is known). A
// path tracer's noise has heavy tails: the median above finds the typical pixel's deviation, well
// below the mean square that the colour weights must accept (on the studio look at 8 samples, 0.034
// against 0.080, and 0.0094 against 0.0047 display RMSE after filtering).
float rootMeanVariance(const std::vector<float>& variance) {
  double sum = 0;
  std::size_t count = 0;
  for (const float v : variance)
    if (v > 0.0f) {
      sum += v;
      ++count;
    }
  return count > 0 ? static_cast<float>(std::sqrt(sum / static_cast<double>(count))) : 0.0f;
}

// Demodulated radiance and the albedo it was divided by (1 where the albedo is too dark).
void demodulate(const Image& image, const FeatureBuffers& f, std::vector<Vec3>& light,
                std::vector<Vec3>& divisor) {
  light.resize(f.albedo.size());
  divisor.resize(f.albedo.size());
  const auto safe = [](float a) { return a > kMinAlbedo ? a : 1.0f; };
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const std::size_t k = f.index(x, y);
      const Vec3& a = f.albedo[k];
      divisor[k] = {safe(a.x), safe(a.y), safe(a.z)};
      const Rgba& c = image.at(x, y);
      light[k] = {c.r / divisor[k].x, c.g / divisor[k].y, c.b / divisor[k].z};
    }
}

}  // namespace

float estimateNoise(const Image& image, const FeatureBuffers& features) {
  std::vector<Vec3> light;
  light.reserve(features.albedo.size());
  for (const Rgba& p : image.pixels()) light.push_back(p.rgb());
  return estimateNoiseOf(light, makeGuides(features, 0), features.width, features.height);
}

Image denoise(const Image& noisy, const FeatureBuffers& features, const DenoiseOptions& options) {
  if (features.width != noisy.width() || features.height != noisy.height())
    throw std::invalid_argument("denoise: the feature buffers' size differs from the image's");
  const int width = noisy.width(), height = noisy.height();
  const std::vector<Guide> guides = makeGuides(features, options.threads);
  std::vector<Vec3> light, divisor;
  demodulate(noisy, features, light, divisor);
  // Measured on the radiance itself, and colours compared at the centre's albedo below: dividing by a
  // dark albedo (a dark background) multiplies the noise, which a global level would not follow.
  std::vector<Vec3> radiance;
  radiance.reserve(light.size());
  for (const Rgba& c : noisy.pixels()) radiance.push_back(c.rgb());
  // A floor keeps the colour weight finite on a noiseless image (it then keeps equal colours only).
  const float noise = std::max(
      {estimateNoiseOf(radiance, guides, width, height), rootMeanVariance(features.variance), 1e-5f});

  const GuidePlanes planes(guides, options);
  // Per pixel: the noise level squared over the pixel's own (its samples' spread, where it is known
  // and larger): a pixel far noisier than the picture (a firefly) then takes its neighbours in.
  std::vector<float> pixelScale(light.size() + kPadding, 1.0f);
  if (!features.variance.empty())
    for (std::size_t k = 0; k < light.size(); ++k)
      if (features.variance[k] > noise * noise) pixelScale[k] = noise * noise / features.variance[k];
  LightPlanes current(light), next(light.size());
  const LightPlanes scale(divisor);
  for (int pass = 0; pass < options.passes; ++pass) {
    const int step = 1 << pass;
    const float sigma = options.colorSigma * noise / static_cast<float>(step);
    const float colorScale = 1.0f / (2.0f * 3.0f * sigma * sigma);  // per channel: the mean of three
    parallelChunks(ChunkPlan(static_cast<std::size_t>(height), 2), options.threads,
                   [&](std::size_t, std::size_t begin, std::size_t end) {
                     RowSums sums(width);
                     for (std::size_t row = begin; row < end; ++row)
                       filterRow(static_cast<int>(row), width, height, step, colorScale, planes, current,
                                 scale, pixelScale.data(), sums, next);
                   });
    std::swap(current, next);
  }

  Image result(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t k = features.index(x, y);
      const Vec3 c = current.at(k) * divisor[k];
      result.at(x, y) = toRgba(c, noisy.at(x, y).a);
    }
  return result;
}

}  // namespace lancer
