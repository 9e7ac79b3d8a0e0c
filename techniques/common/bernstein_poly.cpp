#include "techniques/common/bernstein_poly.h"

#include <array>

namespace tb::techniques {
namespace {

// n! for n <= kMaxFactorial, exact in double up to 22!.
constexpr int kMaxFactorial = 40;

double factorial(int n) {
  static const std::array<double, kMaxFactorial + 1> table = [] {
    std::array<double, kMaxFactorial + 1> t{};
    t[0] = 1;
    for (int k = 1; k <= kMaxFactorial; ++k) t[k] = t[k - 1] * k;
    return t;
  }();
  if (n < 0 || n > kMaxFactorial) throw std::invalid_argument("factorial: out of range");
  return table[size_t(n)];
}

}  // namespace

double binomialCoefficient(int n, int k) {
  return factorial(n) / (factorial(k) * factorial(n - k));
}

double trinomialCoefficient(int i, int j, int k) {
  return factorial(i + j + k) / (factorial(i) * factorial(j) * factorial(k));
}

QuadPoly<double> bilinear(double f00, double f10, double f01, double f11) {
  QuadPoly<double> r(1, 1);
  r.at(0, 0) = f00;
  r.at(1, 0) = f10;
  r.at(0, 1) = f01;
  r.at(1, 1) = f11;
  return r;
}

std::vector<std::vector<double>> bernsteinProductWeights(int m, int n) {
  std::vector<std::vector<double>> weights(size_t(m + 1), std::vector<double>(size_t(n + 1)));
  for (int i = 0; i <= m; ++i) {
    for (int k = 0; k <= n; ++k) {
      weights[i][k] =
          binomialCoefficient(m, i) * binomialCoefficient(n, k) / binomialCoefficient(m + n, i + k);
    }
  }
  return weights;
}

TrianglePoly<double> linear(double f0, double f1, double f2) {
  TrianglePoly<double> r(1);
  r.at(1, 0) = f0;
  r.at(0, 1) = f1;
  r.at(0, 0) = f2;
  return r;
}

QuadPoly<mesh::Vec3d> times(const QuadPoly<double>& a, const mesh::Vec3d& v) {
  QuadPoly<mesh::Vec3d> r(a.deg_u, a.deg_v);
  for (size_t s = 0; s < a.c.size(); ++s) r.c[s] = v * a.c[s];
  return r;
}

TrianglePoly<mesh::Vec3d> times(const TrianglePoly<double>& a, const mesh::Vec3d& v) {
  TrianglePoly<mesh::Vec3d> r(a.degree);
  for (size_t s = 0; s < a.c.size(); ++s) r.c[s] = v * a.c[s];
  return r;
}

}  // namespace tb::techniques
