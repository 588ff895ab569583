// From scene radiance to display values: exposure (in stops) and a tone curve that rolls highlights
// off instead of clipping them, applied to linear radiance before the sRGB or linear encoding.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "lancer/image/image.hpp"

namespace lancer {

enum class ToneMap {
  None,    // clamp at 1 when encoded: the raw values
  Filmic,  // John Hable's Uncharted 2 curve, white point 11.2
  Aces,    // Krzysztof Narkowicz's fit of the ACES reference rendering transform
};

// In the order of the enum; the scene loader and the CLI check names against it.
inline constexpr std::array<std::string_view, 3> kToneMapNames = {"none", "filmic", "aces"};

// The curves on one linear value (x >= 0), each mapping 0 to 0 and approaching 1.
float filmicCurve(float x);
float acesCurve(float x);

// Each pixel's RGB times 2^exposureStops, then through the curve; alpha is untouched. With
// ToneMap::None and exposure 0 nothing changes, to the bit.
void applyToneMap(std::span<Rgba> pixels, ToneMap toneMap, float exposureStops);
void applyToneMap(Image& image, ToneMap toneMap, float exposureStops);

}  // namespace lancer
