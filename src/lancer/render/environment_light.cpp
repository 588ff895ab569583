#include "lancer/render/environment_light.hpp"

#include <algorithm>
#include <cmath>

#include "lancer/render/light_sampling.hpp"

namespace lancer {
namespace {

float luminance(const Vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// The first index whose cumulative value exceeds u (the cell u falls in).
std::size_t findCell(const float* cumulative, std::size_t count, float u) {
  const float* cell = std::upper_bound(cumulative, cumulative + count, u);
  return std::min(static_cast<std::size_t>(cell - cumulative), count - 1);
}

}  // namespace

EnvironmentLight::EnvironmentLight(const SceneEnvironment& environment) : environment_(environment) {
  right_ = cross(environment_.up, environment_.front);
  using Kind = EnvironmentSettings::Kind;
  switch (environment_.kind) {
    case Kind::Uniform:
      black_ = maxComponent(environment_.color) <= 0.0f;
      break;
    case Kind::Gradient:
      black_ = maxComponent(environment_.zenith + environment_.horizon + environment_.ground) <= 0.0f;
      break;
    case Kind::Map:
      black_ = false;
      break;
  }
  black_ = black_ || environment_.strength <= 0.0f;
  if (environment_.kind != Kind::Map || environment_.map.empty()) return;
  const int w = environment_.mapWidth, h = environment_.mapHeight;
  conditional_.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  rowWeight_.resize(static_cast<std::size_t>(h));
  marginal_.resize(static_cast<std::size_t>(h));
  double total = 0;
  for (int y = 0; y < h; ++y) {
    const float sinTheta = std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
    double row = 0;
    float* cumulative = &conditional_[static_cast<std::size_t>(y) * w];
    for (int x = 0; x < w; ++x) {
      row += std::max(0.0f, luminance(environment_.map[static_cast<std::size_t>(y) * w + x])) * sinTheta;
      cumulative[x] = static_cast<float>(row);
    }
    for (int x = 0; x < w; ++x)
      cumulative[x] = row > 0 ? static_cast<float>(cumulative[x] / row) : float(x + 1) / w;
    rowWeight_[static_cast<std::size_t>(y)] = static_cast<float>(row);
    total += row;
    marginal_[static_cast<std::size_t>(y)] = static_cast<float>(total);
  }
  if (!(total > 0)) {  // a black map: nothing to sample
    marginal_.clear();
    black_ = true;
    return;
  }
  for (float& m : marginal_) m = static_cast<float>(m / total);
  marginal_.back() = 1.0f;
  total_ = static_cast<float>(total);
}

void EnvironmentLight::mapCoordinates(const Vec3& direction, float& u, float& v) const {
  const float cosTheta = std::clamp(dot(direction, environment_.up), -1.0f, 1.0f);
  float phi =
      std::atan2(dot(direction, right_), dot(direction, environment_.front)) - environment_.rotationRadians;
  u = phi / (2.0f * kPi) + 0.5f;
  u -= std::floor(u);
  v = std::acos(cosTheta) / kPi;
}

Vec3 EnvironmentLight::mapDirection(float u, float v) const {
  const float phi = (u - 0.5f) * 2.0f * kPi + environment_.rotationRadians;
  const float theta = v * kPi;
  const float sinTheta = std::sin(theta);
  return normalize(environment_.up * std::cos(theta) +
                   (environment_.front * std::cos(phi) + right_ * std::sin(phi)) * sinTheta);
}

Vec3 EnvironmentLight::radiance(const Vec3& direction) const {
  using Kind = EnvironmentSettings::Kind;
  if (black_) return {0, 0, 0};
  switch (environment_.kind) {
    case Kind::Uniform:
      return environment_.color * environment_.strength;
    case Kind::Gradient: {
      const float h = dot(direction, environment_.up);
      if (h < 0.0f) return environment_.ground * environment_.strength;
      return (environment_.horizon * (1.0f - h) + environment_.zenith * h) * environment_.strength;
    }
    case Kind::Map: {
      float u, v;
      mapCoordinates(direction, u, v);
      const int x = std::min(static_cast<int>(u * environment_.mapWidth), environment_.mapWidth - 1);
      const int y = std::min(static_cast<int>(v * environment_.mapHeight), environment_.mapHeight - 1);
      return environment_.map[static_cast<std::size_t>(y) * environment_.mapWidth + x] *
             environment_.strength;
    }
  }
  return {0, 0, 0};
}

Vec3 EnvironmentLight::sample(float u, float v, float& pdf, Vec3& radiance) const {
  const int w = environment_.mapWidth, h = environment_.mapHeight;
  const std::size_t y = findCell(marginal_.data(), marginal_.size(), v);
  const float* row = &conditional_[y * static_cast<std::size_t>(w)];
  const std::size_t x = findCell(row, static_cast<std::size_t>(w), u);
  // Uniform within the cell.
  const float rowStart = y == 0 ? 0.0f : marginal_[y - 1];
  const float rowSpan = marginal_[y] - rowStart;
  const float colStart = x == 0 ? 0.0f : row[x - 1];
  const float colSpan = row[x] - colStart;
  const float fy = rowSpan > 0.0f ? std::clamp((v - rowStart) / rowSpan, 0.0f, 0.999999f) : 0.5f;
  const float fx = colSpan > 0.0f ? std::clamp((u - colStart) / colSpan, 0.0f, 0.999999f) : 0.5f;
  const Vec3 direction = mapDirection((static_cast<float>(x) + fx) / static_cast<float>(w),
                                      (static_cast<float>(y) + fy) / static_cast<float>(h));
  pdf = this->pdf(direction);
  radiance = this->radiance(direction);
  return direction;
}

float EnvironmentLight::pdf(const Vec3& direction) const {
  if (marginal_.empty()) return 0.0f;
  float u, v;
  mapCoordinates(direction, u, v);
  const int w = environment_.mapWidth, h = environment_.mapHeight;
  const int x = std::min(static_cast<int>(u * w), w - 1);
  const int y = std::min(static_cast<int>(v * h), h - 1);
  const float cellSin = std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
  const float cosTheta = std::clamp(dot(direction, environment_.up), -1.0f, 1.0f);
  const float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
  if (!(sinTheta > 0.0f)) return 0.0f;
  const float cell =
      std::max(0.0f, luminance(environment_.map[static_cast<std::size_t>(y) * w + x])) * cellSin;
  // p(u, v) = cell / (total / (w h)), constant over the cell; per solid angle divide by the
  // Jacobian 2 pi^2 sin(theta) of the direction itself.
  const float pUv = cell * static_cast<float>(w) * static_cast<float>(h) / total_;
  return pUv / (2.0f * kPi * kPi * sinTheta);
}

}  // namespace lancer
