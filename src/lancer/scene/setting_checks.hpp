// One check per render setting, whoever sets it: the scene file (`render.width`), the command line
// (`--width`) or Python (`width=`). Each takes the value and how the caller names the setting, and
// throws InputError there with one wording, "NAME must be between 1 and 32768, found 0", so that a
// value one front end accepts the others accept too (the limits are in render_limits.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "lancer/scene/scene_description.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// Where the value came from (a file position, or the option: "--width") and its name as spelled
// there ("render.width", "--width", "width").
struct SettingName {
  SourceLocation where;
  std::string name;
};

// Integers: returned as int once in range.
int checkWidth(std::int64_t value, const SettingName& name);     // 1 to kMaxRenderSide
int checkHeight(std::int64_t value, const SettingName& name);    // 1 to kMaxRenderSide
int checkSamples(std::int64_t value, const SettingName& name);   // 1 to kMaxSamples
int checkMaxDepth(std::int64_t value, const SettingName& name);  // 0 to kMaxDepth
int checkThreads(std::int64_t value, const SettingName& name);   // 0 (one per usable CPU) to kMaxThreads
int checkFrames(std::int64_t value, const SettingName& name);    // 1 to kMaxFrames
int checkBitDepth(std::int64_t value, const SettingName& name);  // 8 or 16
int checkLoop(std::int64_t value, const SettingName& name);      // -1 (play once), 0 (forever) to kMaxLoop

// Numbers: finite and in range.
float checkExposure(double stops, const SettingName& name);       // -kMaxExposureStops to kMaxExposureStops
float checkNoise(double value, const SettingName& name);          // greater than 0 and less than 1
float checkAdaptiveNoise(double value, const SettingName& name);  // greater than 0 and less than 1
double checkFps(double value, const SettingName& name);           // kMinFps to kMaxFps frames a second

// The regular and stratified samplers lay an n x n grid over the pixel for the Whitted model: a
// sample count that is no perfect square is refused there (path and AO, and the adaptive sampler,
// take any).
void checkSampleGrid(int samples, SamplerKind sampler, IntegratorKind integrator, const SettingName& name);

// The camera's orbit from the command line (view_presets.hpp): azimuth any finite angle, elevation
// -90 to 90 degrees, zoom kMinZoom to kMaxZoom.
double checkAzimuth(double degrees, const SettingName& name);
double checkElevation(double degrees, const SettingName& name);
double checkZoom(double factor, const SettingName& name);

}  // namespace lancer
