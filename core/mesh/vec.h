// Small fixed-size vectors templated on the scalar, so evaluators run in float,
// double and a counting scalar with one code path.
#pragma once

#include <cmath>

namespace tb::mesh {

template <class T>
struct Vec2T {
  T x{}, y{};
};

template <class T>
struct Vec3T {
  T x{}, y{}, z{};

  friend Vec3T operator+(const Vec3T& a, const Vec3T& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend Vec3T operator-(const Vec3T& a, const Vec3T& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend Vec3T operator*(const Vec3T& a, const T& s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3T operator*(const T& s, const Vec3T& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend bool operator==(const Vec3T& a, const Vec3T& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
  T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <class T>
T dot(const Vec3T<T>& a, const Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <class T>
Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class T>
T length(const Vec3T<T>& a) {
  using std::sqrt;
  return sqrt(dot(a, a));
}

// Returns a unchanged when it has zero length (a degenerate normal stays zero
// rather than turning into NaN).
template <class T>
Vec3T<T> normalize(const Vec3T<T>& a) {
  const T len = length(a);
  if (!(len > T(0))) return a;
  return a * (T(1) / len);
}

template <class To, class From>
Vec3T<To> vecCast(const Vec3T<From>& a) {
  return {To(a.x), To(a.y), To(a.z)};
}

using Vec2d = Vec2T<double>;
using Vec3d = Vec3T<double>;
using Vec3f = Vec3T<float>;

}  // namespace tb::mesh
