// Small 3-vectors of float (geometry, colours) and double (file coordinates before recentring).
// Plain aggregates with inline operators so the hot loops see straight-line arithmetic.
// Map: docs/architecture.md (the path of a ray through the modules).
#pragma once

#include <algorithm>
#include <cmath>

namespace lancer {

template <typename T>
struct Vec3T {
  T x = 0, y = 0, z = 0;

  constexpr T operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  constexpr T& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }

  constexpr Vec3T operator-() const { return {-x, -y, -z}; }
  constexpr Vec3T& operator+=(const Vec3T& b) {
    x += b.x;
    y += b.y;
    z += b.z;
    return *this;
  }
  constexpr Vec3T& operator-=(const Vec3T& b) {
    x -= b.x;
    y -= b.y;
    z -= b.z;
    return *this;
  }
  constexpr Vec3T& operator*=(T s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr Vec3T& operator*=(const Vec3T& b) {
    x *= b.x;
    y *= b.y;
    z *= b.z;
    return *this;
  }
  friend constexpr bool operator==(const Vec3T&, const Vec3T&) = default;
};

using Vec3 = Vec3T<float>;
using Vec3d = Vec3T<double>;

template <typename T>
constexpr Vec3T<T> operator+(Vec3T<T> a, const Vec3T<T>& b) {
  return a += b;
}
template <typename T>
constexpr Vec3T<T> operator-(Vec3T<T> a, const Vec3T<T>& b) {
  return a -= b;
}
template <typename T>
constexpr Vec3T<T> operator*(Vec3T<T> a, T s) {
  return a *= s;
}
template <typename T>
constexpr Vec3T<T> operator*(T s, Vec3T<T> a) {
  return a *= s;
}
template <typename T>
constexpr Vec3T<T> operator*(Vec3T<T> a, const Vec3T<T>& b) {
  return a *= b;
}
template <typename T>
constexpr Vec3T<T> operator/(const Vec3T<T>& a, T s) {
  return a * (T(1) / s);
}

template <typename T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
inline T length(const Vec3T<T>& a) {
  return std::sqrt(dot(a, a));
}
template <typename T>
inline Vec3T<T> normalize(const Vec3T<T>& a) {
  T len = length(a);
  return len > T(0) ? a * (T(1) / len) : a;
}
template <typename T>
constexpr Vec3T<T> min(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T>
constexpr Vec3T<T> max(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <typename T>
constexpr T maxComponent(const Vec3T<T>& a) {
  return std::max({a.x, a.y, a.z});
}
template <typename T>
inline Vec3T<T> abs(const Vec3T<T>& a) {
  return {std::abs(a.x), std::abs(a.y), std::abs(a.z)};
}
template <typename T>
inline bool isFinite(const Vec3T<T>& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

inline Vec3 toFloat(const Vec3d& a) {
  return {static_cast<float>(a.x), static_cast<float>(a.y), static_cast<float>(a.z)};
}
inline Vec3d toDouble(const Vec3& a) { return {a.x, a.y, a.z}; }

}  // namespace lancer
