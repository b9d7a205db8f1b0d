// vec3.h: a small 3-vector used by every kernel.
//
// Storage in shadetool is flat arrays of double (#V by 3); Vec3<T> is the value type the kernels
// compute with for points and directions; normals have their own type, Normal3 (below), because
// they transform differently: lib/shadetool/core/affine.h's transform_normal takes only a Normal3, and
// transform_point / transform_vector refuse one, so neither mistake compiles.
#pragma once

#include <cmath>
#include <cstddef>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

template <class T>
struct Vec3 {
  T x{}, y{}, z{};

  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <class U>
  constexpr explicit Vec3(const Vec3<U>& o) : x(T(o.x)), y(T(o.y)), z(T(o.z)) {}

  constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr const T& operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
};

using Vec3d = Vec3<double>;
using Vec3f = Vec3<float>;

// A surface normal: a Vec3 that transforms by the cofactor of the map (core/affine.h,
// transform_normal), never by the map itself. Its own type (pbrt-v4's Normal3) so that a point or
// a direction cannot be passed where a normal is transformed: Normal3 converts to Vec3 (for dot,
// cross, length), but a Vec3 becomes a Normal3 only by saying so, Normal3d(v). No cost: the same
// three values.
template <class T>
struct Normal3 : Vec3<T> {
  constexpr Normal3() = default;
  constexpr Normal3(T x_, T y_, T z_) : Vec3<T>(x_, y_, z_) {}
  constexpr explicit Normal3(const Vec3<T>& v) : Vec3<T>(v) {}
};

using Normal3d = Normal3<double>;

template <class T> constexpr Vec3<T> operator+(Vec3<T> a, const Vec3<T>& b) { return a += b; }
template <class T> constexpr Vec3<T> operator-(Vec3<T> a, const Vec3<T>& b) { return a -= b; }
template <class T> constexpr Vec3<T> operator-(const Vec3<T>& a) { return {-a.x, -a.y, -a.z}; }
template <class T> constexpr Vec3<T> operator*(Vec3<T> a, T s) { return a *= s; }
template <class T> constexpr Vec3<T> operator*(T s, Vec3<T> a) { return a *= s; }
template <class T> constexpr bool operator==(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}
template <class T> constexpr bool operator!=(const Vec3<T>& a, const Vec3<T>& b) { return !(a == b); }

template <class T> constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T> constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> constexpr T squared_length(const Vec3<T>& a) { return dot(a, a); }

// Euclidean length without overflow or underflow for any finite input: the largest component is
// factored out before squaring (1e200 and 1e-200 components both survive).
template <class T> T length(const Vec3<T>& a) {
  const T m = std::fmax(std::fabs(a.x), std::fmax(std::fabs(a.y), std::fabs(a.z)));
  if (!(m > T(0)) || !std::isfinite(m)) return m;  // zero, NaN or Inf: nothing to scale
  const Vec3<T> s{a.x / m, a.y / m, a.z / m};
  return m * std::sqrt(dot(s, s));
}

// Unit vector along a, or `fallback` when a has zero, non-finite or unrepresentable length.
// Checks its divisor: never returns NaN for finite input.
template <class T> Vec3<T> normalized_or(const Vec3<T>& a, const Vec3<T>& fallback) {
  const T l = length(a);
  if (!(l > T(0)) || !std::isfinite(l)) return fallback;
  return {a.x / l, a.y / l, a.z / l};
}

template <class T> bool is_finite(const Vec3<T>& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace shadetool
#pragma GCC visibility pop
