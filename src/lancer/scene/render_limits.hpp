// What a scene may ask for, and the names of its choices: one table read by the scene loader and by
// the command line, so that a value one accepts the other accepts too, with the same words.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// An image side of more pixels than this is refused before anything is allocated (a whole
// 32768 x 32768 image already takes 16 GiB as float RGBA); the Image class itself allows up to
// kMaxImageSide (image.hpp), GIF's format limit.
inline constexpr int kMaxRenderSide = 32768;
inline constexpr int kMaxSamples = 1024;
inline constexpr int kMaxDepth = 64;
inline constexpr int kMaxFrames = 10000;
// An animation's frame rate: a frame a hundred seconds to a hundred a second.
inline constexpr double kMinFps = 0.01;
inline constexpr double kMaxFps = 100;
// Repeats of an animated GIF or PNG after the first showing (both formats store 16 bits).
inline constexpr int kMaxLoop = 65535;
inline constexpr int kMaxThreads = 1024;
// render.exposure and --exposure, in stops: 2^20 is a million times brighter or darker.
inline constexpr double kMaxExposureStops = 20;
// --zoom: the camera up to a thousand times closer or farther.
inline constexpr double kMinZoom = 0.001;
inline constexpr double kMaxZoom = 1000;
// Text drawn into a picture (an animation's label, a legend's title and units), in characters: a
// line this long already spans a 1920-pixel picture several times.
inline constexpr std::size_t kMaxDrawnText = 200;
// The width or precision a label's format may ask for ({time:12.6g}).
inline constexpr std::uint64_t kMaxLabelFormatNumber = 64;

// Annotations (docs/annotations.md): colour bands, isolines and arrows per mesh.
inline constexpr int kMaxBands = 256;
inline constexpr int kMaxIsolineCount = 1000;
inline constexpr int kMaxArrowCount = 100'000;

// In the order of the enums they name (checked below).
inline constexpr std::array<std::string_view, 4> kShadingNames = {"flat", "gouraud", "phong", "unlit"};
inline constexpr std::array<std::string_view, 2> kProjectionNames = {"perspective", "orthographic"};
inline constexpr std::array<std::string_view, 3> kSamplerNames = {"regular", "stratified", "adaptive"};
inline constexpr std::array<std::string_view, 3> kIntegratorNames = {"whitted", "path", "ao"};
inline constexpr std::array<std::string_view, 3> kLegendPlacementNames = {"none", "right", "bottom"};
inline constexpr std::array<std::string_view, 5> kLightTypeNames = {"point", "sun", "sphere", "rect", "disk"};
static_assert(kIntegratorNames[static_cast<int>(IntegratorKind::AmbientOcclusion)] == "ao");
static_assert(kLightTypeNames[static_cast<int>(LightType::Disk)] == "disk");
static_assert(kShadingNames[static_cast<int>(ShadingMode::Gouraud)] == "gouraud" &&
              kShadingNames[static_cast<int>(ShadingMode::Phong)] == "phong" &&
              kShadingNames[static_cast<int>(ShadingMode::Unlit)] == "unlit");
static_assert(kLegendPlacementNames[static_cast<int>(LegendPlacement::Bottom)] == "bottom");
static_assert(kProjectionNames[static_cast<int>(Projection::Orthographic)] == "orthographic");
static_assert(kSamplerNames[static_cast<int>(SamplerKind::Stratified)] == "stratified" &&
              kSamplerNames[static_cast<int>(SamplerKind::Adaptive)] == "adaptive");

// The enum value a name stands for, or nothing for a name not in the table.
template <typename Enum, std::size_t N>
std::optional<Enum> enumFromName(const std::array<std::string_view, N>& names, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<Enum>(i);
  return std::nullopt;
}

}  // namespace lancer
