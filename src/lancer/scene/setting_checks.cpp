#include "lancer/scene/setting_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string_view>

#include "lancer/scene/render_limits.hpp"

namespace lancer {
namespace {

int checkedInteger(std::int64_t value, std::int64_t low, std::int64_t high, const SettingName& name,
                   const char* note = "") {
  if (value < low || value > high)
    throw InputError(name.where, fmt::format("{} must be between {} and {}{}, found {}", name.name, low, high,
                                             note, value));
  return static_cast<int>(value);
}

double checkedNumber(double value, double low, double high, const SettingName& name, const char* what) {
  if (!std::isfinite(value) || value < low || value > high)
    throw InputError(name.where, fmt::format("{} must be {} between {} and {}, found {}", name.name, what,
                                             low, high, value));
  return value;
}

}  // namespace

int checkWidth(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, 1, kMaxRenderSide, name);
}
int checkHeight(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, 1, kMaxRenderSide, name);
}
int checkSamples(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, 1, kMaxSamples, name);
}
int checkMaxDepth(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, 0, kMaxDepth, name);
}
int checkThreads(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, 0, kMaxThreads, name, " (0: one per usable CPU)");
}
int checkFrames(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, 1, kMaxFrames, name);
}

int checkLoop(std::int64_t value, const SettingName& name) {
  return checkedInteger(value, -1, kMaxLoop, name, " (0: forever, -1: play once)");
}

int checkBitDepth(std::int64_t value, const SettingName& name) {
  if (value != 8 && value != 16)
    throw InputError(name.where, fmt::format("{} must be 8 or 16, found {}", name.name, value));
  return static_cast<int>(value);
}

float checkExposure(double stops, const SettingName& name) {
  return static_cast<float>(
      checkedNumber(stops, -kMaxExposureStops, kMaxExposureStops, name, "a number of stops"));
}

double checkFps(double value, const SettingName& name) {
  return checkedNumber(value, kMinFps, kMaxFps, name, "a number of frames per second");
}

namespace {

// An error target strictly between 0 and 1 (NaN fails the test too); `what` says what it measures.
float checkErrorTarget(double value, const SettingName& name, std::string_view what) {
  if (!(value > 0 && value < 1))
    throw InputError(name.where,
                     fmt::format("{} must be greater than 0 and less than 1 ({}, e.g. 0.01), found {}",
                                 name.name, what, value));
  return static_cast<float>(value);
}

}  // namespace

float checkNoise(double value, const SettingName& name) {
  return checkErrorTarget(value, name, "a relative error");
}

float checkAdaptiveNoise(double value, const SettingName& name) {
  return checkErrorTarget(value, name, "the error of the displayed value, a fraction of white");
}

void checkSampleGrid(int samples, SamplerKind sampler, IntegratorKind integrator, const SettingName& name) {
  if (integrator != IntegratorKind::Whitted || sampler == SamplerKind::Adaptive) return;
  const auto below = static_cast<std::int64_t>(std::floor(std::sqrt(static_cast<double>(samples))));
  if (below * below == samples) return;
  throw InputError(
      name.where,
      fmt::format("{} must be a perfect square (an n x n sub-pixel grid) for the {} sampler, found "
                  "{}; use {} or {}, or the adaptive sampler, or the path or ao integrator",
                  name.name, kSamplerNames[static_cast<std::size_t>(sampler)], samples, below * below,
                  (below + 1) * (below + 1)));
}

double checkAzimuth(double degrees, const SettingName& name) {
  if (!std::isfinite(degrees))
    throw InputError(name.where,
                     fmt::format("{} must be a finite number of degrees, found {}", name.name, degrees));
  return degrees;
}

double checkElevation(double degrees, const SettingName& name) {
  return checkedNumber(degrees, -90, 90, name, "a number of degrees");
}

double checkZoom(double factor, const SettingName& name) {
  return checkedNumber(factor, kMinZoom, kMaxZoom, name, "a factor");
}

}  // namespace lancer
