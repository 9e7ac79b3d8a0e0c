// Polynomials in Bernstein form over the quad domain [0,1]^2 (tensor product, bi-degree
// m x n) and over the triangle (barycentric u, v, w, total degree n), with scalar (double)
// or vector (Vec3d) coefficients: sums, products (a product of Bernstein polynomials is a
// Bernstein polynomial of the summed degree with positive weights), directional
// derivatives and degree elevation. For the cone bounds of techniques/common/patch_bounds.h;
// plain loops, no attention to speed (a few hundred coefficients per patch).
//
// Quad coefficients c[i + (m + 1) j] (i along u). Triangle coefficients b_ijk (i + j + k =
// n; i the power of u, corner 0's weight) in rows of descending i, each by descending j.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/mesh/vec.h"

namespace tb::techniques {

double binomialCoefficient(int n, int k);
// (i + j + k)! / (i! j! k!)
double trinomialCoefficient(int i, int j, int k);

constexpr int triangleNetSize(int degree) { return (degree + 1) * (degree + 2) / 2; }
constexpr int triangleNetSlot(int degree, int i, int j) {
  return (degree - i) * (degree - i + 1) / 2 + (degree - i - j);
}

// Products of coefficients: scalar x scalar, scalar x vector, vector x vector (cross).
inline double coefficientProduct(double a, double b) { return a * b; }
inline mesh::Vec3d coefficientProduct(double a, const mesh::Vec3d& b) { return b * a; }
inline mesh::Vec3d coefficientProduct(const mesh::Vec3d& a, double b) { return a * b; }
inline mesh::Vec3d coefficientProduct(const mesh::Vec3d& a, const mesh::Vec3d& b) {
  return cross(a, b);
}

template <class V>
struct QuadPoly {
  int deg_u = 0, deg_v = 0;
  std::vector<V> c;

  QuadPoly() = default;
  QuadPoly(int m, int n) : deg_u(m), deg_v(n), c(size_t((m + 1) * (n + 1)), V{}) {}
  V& at(int i, int j) { return c[size_t(i + (deg_u + 1) * j)]; }
  const V& at(int i, int j) const { return c[size_t(i + (deg_u + 1) * j)]; }
};

template <class V>
struct TrianglePoly {
  int degree = 0;
  std::vector<V> c;

  TrianglePoly() = default;
  explicit TrianglePoly(int n) : degree(n), c(size_t(triangleNetSize(n)), V{}) {}
  V& at(int i, int j) { return c[size_t(triangleNetSlot(degree, i, j))]; }
  const V& at(int i, int j) const { return c[size_t(triangleNetSlot(degree, i, j))]; }
};

// The bilinear (bi-degree 1) polynomial with values f00 at (0,0), f10 at (1,0), f01 at
// (0,1) and f11 at (1,1); exact for any linear function of u and v.
QuadPoly<double> bilinear(double f00, double f10, double f01, double f11);
// The linear triangle polynomial with values f0, f1, f2 at corners 0, 1, 2.
TrianglePoly<double> linear(double f0, double f1, double f2);

// weights[i][k] = C(m, i) C(n, k) / C(m + n, i + k): B^m_i B^n_k = weight B^{m+n}_{i+k}.
std::vector<std::vector<double>> bernsteinProductWeights(int m, int n);

template <class A, class B>
auto operator*(const QuadPoly<A>& a, const QuadPoly<B>& b)
    -> QuadPoly<decltype(coefficientProduct(A{}, B{}))> {
  using R = decltype(coefficientProduct(A{}, B{}));
  QuadPoly<R> r(a.deg_u + b.deg_u, a.deg_v + b.deg_v);
  const auto along_u = bernsteinProductWeights(a.deg_u, b.deg_u);
  const auto along_v = bernsteinProductWeights(a.deg_v, b.deg_v);
  for (int j = 0; j <= a.deg_v; ++j) {
    for (int i = 0; i <= a.deg_u; ++i) {
      for (int l = 0; l <= b.deg_v; ++l) {
        for (int k = 0; k <= b.deg_u; ++k) {
          R& slot = r.at(i + k, j + l);
          slot =
              slot + coefficientProduct(a.at(i, j), b.at(k, l)) * (along_u[i][k] * along_v[j][l]);
        }
      }
    }
  }
  return r;
}

template <class A, class B>
auto operator*(const TrianglePoly<A>& a, const TrianglePoly<B>& b)
    -> TrianglePoly<decltype(coefficientProduct(A{}, B{}))> {
  using R = decltype(coefficientProduct(A{}, B{}));
  TrianglePoly<R> r(a.degree + b.degree);
  for (int i1 = 0; i1 <= a.degree; ++i1) {
    for (int j1 = 0; i1 + j1 <= a.degree; ++j1) {
      const int k1 = a.degree - i1 - j1;
      for (int i2 = 0; i2 <= b.degree; ++i2) {
        for (int j2 = 0; i2 + j2 <= b.degree; ++j2) {
          const int k2 = b.degree - i2 - j2;
          const double weight = trinomialCoefficient(i1, j1, k1) *
                                trinomialCoefficient(i2, j2, k2) /
                                trinomialCoefficient(i1 + i2, j1 + j2, k1 + k2);
          R& slot = r.at(i1 + i2, j1 + j2);
          slot = slot + coefficientProduct(a.at(i1, j1), b.at(i2, j2)) * weight;
        }
      }
    }
  }
  return r;
}

// A scalar polynomial times a constant vector.
QuadPoly<mesh::Vec3d> times(const QuadPoly<double>& a, const mesh::Vec3d& v);
TrianglePoly<mesh::Vec3d> times(const TrianglePoly<double>& a, const mesh::Vec3d& v);

// Degree raised to (m, n) >= the polynomial's own, the same function.
template <class V>
QuadPoly<V> elevated(const QuadPoly<V>& a, int m, int n) {
  if (m < a.deg_u || n < a.deg_v) throw std::invalid_argument("elevated: degree lowered");
  QuadPoly<V> r = a;
  while (r.deg_u < m) {  // c'_i = (i c_{i-1} + (d + 1 - i) c_i) / (d + 1)
    QuadPoly<V> next(r.deg_u + 1, r.deg_v);
    const double d1 = r.deg_u + 1;
    for (int j = 0; j <= r.deg_v; ++j) {
      for (int i = 0; i <= next.deg_u; ++i) {
        V value{};
        if (i > 0) value = value + r.at(i - 1, j) * (i / d1);
        if (i < d1) value = value + r.at(i, j) * ((d1 - i) / d1);
        next.at(i, j) = value;
      }
    }
    r = std::move(next);
  }
  while (r.deg_v < n) {
    QuadPoly<V> next(r.deg_u, r.deg_v + 1);
    const double d1 = r.deg_v + 1;
    for (int j = 0; j <= next.deg_v; ++j) {
      for (int i = 0; i <= r.deg_u; ++i) {
        V value{};
        if (j > 0) value = value + r.at(i, j - 1) * (j / d1);
        if (j < d1) value = value + r.at(i, j) * ((d1 - j) / d1);
        next.at(i, j) = value;
      }
    }
    r = std::move(next);
  }
  return r;
}

template <class V>
TrianglePoly<V> elevated(const TrianglePoly<V>& a, int n) {
  if (n < a.degree) throw std::invalid_argument("elevated: degree lowered");
  TrianglePoly<V> r = a;
  while (r.degree < n) {  // b'_ijk = (i b_{i-1,j,k} + j b_{i,j-1,k} + k b_{i,j,k-1}) / (d + 1)
    TrianglePoly<V> next(r.degree + 1);
    const double d1 = r.degree + 1;
    for (int i = 0; i <= next.degree; ++i) {
      for (int j = 0; i + j <= next.degree; ++j) {
        const int k = next.degree - i - j;
        V value{};
        if (i > 0) value = value + r.at(i - 1, j) * (i / d1);
        if (j > 0) value = value + r.at(i, j - 1) * (j / d1);
        if (k > 0) value = value + r.at(i, j) * (k / d1);
        next.at(i, j) = value;
      }
    }
    r = std::move(next);
  }
  return r;
}

// Sum, raised to the larger degree.
template <class V>
QuadPoly<V> operator+(const QuadPoly<V>& a, const QuadPoly<V>& b) {
  const int m = std::max(a.deg_u, b.deg_u), n = std::max(a.deg_v, b.deg_v);
  QuadPoly<V> r = elevated(a, m, n);
  const QuadPoly<V> s = elevated(b, m, n);
  for (size_t k = 0; k < r.c.size(); ++k) r.c[k] = r.c[k] + s.c[k];
  return r;
}

template <class V>
TrianglePoly<V> operator+(const TrianglePoly<V>& a, const TrianglePoly<V>& b) {
  const int n = std::max(a.degree, b.degree);
  TrianglePoly<V> r = elevated(a, n);
  const TrianglePoly<V> s = elevated(b, n);
  for (size_t k = 0; k < r.c.size(); ++k) r.c[k] = r.c[k] + s.c[k];
  return r;
}

// ∂/∂u and ∂/∂v (degree 0 stays a zero constant).
template <class V>
QuadPoly<V> derivativeU(const QuadPoly<V>& a) {
  if (a.deg_u == 0) return QuadPoly<V>(0, a.deg_v);
  QuadPoly<V> r(a.deg_u - 1, a.deg_v);
  for (int j = 0; j <= r.deg_v; ++j) {
    for (int i = 0; i <= r.deg_u; ++i) r.at(i, j) = (a.at(i + 1, j) - a.at(i, j)) * double(a.deg_u);
  }
  return r;
}

template <class V>
QuadPoly<V> derivativeV(const QuadPoly<V>& a) {
  if (a.deg_v == 0) return QuadPoly<V>(a.deg_u, 0);
  QuadPoly<V> r(a.deg_u, a.deg_v - 1);
  for (int j = 0; j <= r.deg_v; ++j) {
    for (int i = 0; i <= r.deg_u; ++i) r.at(i, j) = (a.at(i, j + 1) - a.at(i, j)) * double(a.deg_v);
  }
  return r;
}

// Derivative toward corner 1 (d/dv - d/du) or corner 2 (d/dw - d/du) of a triangle
// polynomial: n (b_{i,j+1,k} - b_{i+1,j,k}), resp. n (b_{i,j,k+1} - b_{i+1,j,k}).
template <class V>
TrianglePoly<V> derivativeToward(const TrianglePoly<V>& a, int corner) {
  if (corner != 1 && corner != 2) throw std::invalid_argument("derivativeToward: corner 1 or 2");
  if (a.degree == 0) return TrianglePoly<V>(0);
  TrianglePoly<V> r(a.degree - 1);
  for (int i = 0; i <= r.degree; ++i) {
    for (int j = 0; i + j <= r.degree; ++j) {
      const V& head = corner == 1 ? a.at(i, j + 1) : a.at(i, j);  // b_{i,j,k+1} is at (i, j)
      r.at(i, j) = (head - a.at(i + 1, j)) * double(a.degree);
    }
  }
  return r;
}

}  // namespace tb::techniques
