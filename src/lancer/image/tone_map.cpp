#include "lancer/image/tone_map.hpp"

#include <algorithm>
#include <cmath>

namespace lancer {
namespace {

// John Hable, "Filmic Tonemapping Operators" (2010, the Uncharted 2 curve): shoulder strength A,
// linear strength B, linear angle C, toe strength D, toe numerator E, toe denominator F.
double hablePartial(double x) {
  constexpr double A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
  return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

}  // namespace

float filmicCurve(float x) {
  // Hable's post scales the input by an exposure bias of 2 and divides by the curve at the white
  // point W = 11.2, so that W maps to 1.
  constexpr double kExposureBias = 2.0, kWhite = 11.2;
  static const double whiteScale = 1.0 / hablePartial(kWhite);
  const double v = hablePartial(kExposureBias * std::max(0.0f, x)) * whiteScale;
  return static_cast<float>(std::clamp(v, 0.0, 1.0));
}

float acesCurve(float x) {
  // Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): a rational fit of the ACES RRT +
  // ODT, with his 0.6 pre-exposure so that scene values keep about the brightness they had.
  constexpr double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  const double v = 0.6 * std::max(0.0f, x);
  return static_cast<float>(std::clamp(v * (a * v + b) / (v * (c * v + d) + e), 0.0, 1.0));
}

void applyToneMap(std::span<Rgba> pixels, ToneMap toneMap, float exposureStops) {
  if (toneMap == ToneMap::None && exposureStops == 0.0f) return;
  const float scale = std::exp2(exposureStops);
  const auto curve = [toneMap](float v) {
    switch (toneMap) {
      case ToneMap::None:
        return v;
      case ToneMap::Filmic:
        return filmicCurve(v);
      case ToneMap::Aces:
        return acesCurve(v);
    }
    return v;
  };
  for (Rgba& p : pixels) {
    p.r = curve(p.r * scale);
    p.g = curve(p.g * scale);
    p.b = curve(p.b * scale);
  }
}

void applyToneMap(Image& image, ToneMap toneMap, float exposureStops) {
  applyToneMap(image.pixels(), toneMap, exposureStops);
}

}  // namespace lancer
