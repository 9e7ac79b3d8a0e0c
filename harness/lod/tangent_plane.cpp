#include "harness/lod/tangent_plane.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "techniques/common/bernstein_poly.h"

namespace tb::lod {
namespace {

using techniques::QuadPoly;
using techniques::TrianglePoly;

// One coordinate of a vector polynomial, as a scalar polynomial of the same shape.
template <class Poly, class ScalarPoly>
ScalarPoly coordinate(const Poly& p, int axis, ScalarPoly shape) {
  shape.c.resize(p.c.size());
  for (size_t k = 0; k < p.c.size(); ++k) shape.c[k] = p.c[k][axis];
  return shape;
}

// q . n as a scalar polynomial (the sum of the three coordinate products).
template <class ScalarPoly, class Poly>
ScalarPoly dotPoly(const Poly& q, const Poly& n, const ScalarPoly& shape_q,
                   const ScalarPoly& shape_n) {
  ScalarPoly sum = coordinate(q, 0, shape_q) * coordinate(n, 0, shape_n);
  for (int axis = 1; axis < 3; ++axis) {
    sum = sum + coordinate(q, axis, shape_q) * coordinate(n, axis, shape_n);
  }
  return sum;
}

// {n_k, -w'_k} from the degree-raised normal patch and q . n, negated when mirrored.
std::vector<TangentPlaneCoefficient> pack(const std::vector<mesh::Vec3d>& normal,
                                          const std::vector<double>& q_dot_n, bool mirrored) {
  const double sign = mirrored ? -1 : 1;
  std::vector<TangentPlaneCoefficient> out(normal.size());
  for (size_t k = 0; k < normal.size(); ++k) {
    out[k] = {sign * normal[k][0], sign * normal[k][1], sign * normal[k][2], -sign * q_dot_n[k]};
  }
  return out;
}

std::vector<TangentPlaneCoefficient> quadCoefficients(const std::vector<mesh::Vec3d>& net,
                                                      int degree, bool mirrored) {
  QuadPoly<mesh::Vec3d> q(degree, degree);
  q.c = net;
  const QuadPoly<mesh::Vec3d> n = techniques::derivativeU(q) * techniques::derivativeV(q);
  const QuadPoly<double> q_dot_n =
      dotPoly(q, n, QuadPoly<double>(degree, degree), QuadPoly<double>(n.deg_u, n.deg_v));
  const QuadPoly<mesh::Vec3d> raised = techniques::elevated(n, q_dot_n.deg_u, q_dot_n.deg_v);
  return pack(raised.c, q_dot_n.c, mirrored);
}

std::vector<TangentPlaneCoefficient> triangleCoefficients(const std::vector<mesh::Vec3d>& net,
                                                          int degree, bool mirrored) {
  TrianglePoly<mesh::Vec3d> q(degree);
  q.c = net;
  const TrianglePoly<mesh::Vec3d> n =
      techniques::derivativeToward(q, 1) * techniques::derivativeToward(q, 2);
  const TrianglePoly<double> q_dot_n =
      dotPoly(q, n, TrianglePoly<double>(degree), TrianglePoly<double>(n.degree));
  const TrianglePoly<mesh::Vec3d> raised = techniques::elevated(n, q_dot_n.degree);
  return pack(raised.c, q_dot_n.c, mirrored);
}

template <class Poly>
double largestCoefficient(const Poly& p) {
  double largest = 0;
  for (const mesh::Vec3d& c : p.c) largest = std::max(largest, length(c));
  return largest;
}

// {G1, G2}: the largest coefficient of the first and of the second derivatives.
template <class Poly, class D1, class D2>
std::array<double, 2> derivativeBounds(const Poly& q, const D1& along1, const D2& along2) {
  const Poly first[2] = {along1(q), along2(q)};
  const Poly second[3] = {along1(first[0]), along1(first[1]), along2(first[1])};
  double g1 = 0, g2 = 0;
  for (const Poly& p : first) g1 = std::max(g1, largestCoefficient(p));
  for (const Poly& p : second) g2 = std::max(g2, largestCoefficient(p));
  return {g1, g2};
}

size_t netSize(bool quad, int degree) {
  return quad ? size_t((degree + 1) * (degree + 1)) : size_t(techniques::triangleNetSize(degree));
}

}  // namespace

TangentPlaneChordBound tangentPlaneChordBound(techniques::PatchDomain domain,
                                              const techniques::PatchCullBounds& bounds,
                                              const mesh::Vec3d& origin) {
  TangentPlaneChordBound bound;
  const bool quad = domain == techniques::PatchDomain::kQuad;
  const int degree = bounds.bezier_degree;
  if (bounds.bezier_net.empty() || degree < 1 ||
      bounds.bezier_net.size() != netSize(quad, degree)) {
    return bound;
  }
  for (const mesh::Vec3d& p : bounds.bezier_net)
    bound.reach = std::max(bound.reach, length(p - origin));
  std::array<double, 2> g;
  if (quad) {
    QuadPoly<mesh::Vec3d> q(degree, degree);
    q.c = bounds.bezier_net;
    g = derivativeBounds(
        q, [](const auto& p) { return techniques::derivativeU(p); },
        [](const auto& p) { return techniques::derivativeV(p); });
  } else {
    TrianglePoly<mesh::Vec3d> q(degree);
    q.c = bounds.bezier_net;
    g = derivativeBounds(
        q, [](const auto& p) { return techniques::derivativeToward(p, 1); },
        [](const auto& p) { return techniques::derivativeToward(p, 2); });
  }
  bound.first_times_second = g[0] * g[1];
  bound.second_squared = g[1] * g[1];
  return bound;
}

std::array<double, 2> chordFactors(tess::Domain domain, float level) {
  tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};
  const tess::Tessellation t = tess::tessellate(domain, tess::Spacing::kInteger, levels);
  const bool quad = domain == tess::Domain::kQuad;
  auto coords = [&](uint32_t i) {
    const tess::DomainPoint& p = t.points[i];
    return quad ? std::array<double, 2>{p[0], p[1]} : std::array<double, 2>{p[1], p[2]};
  };
  std::array<double, 2> k{0, 0};
  for (const std::array<uint32_t, 3>& tri : t.triangles) {
    double best_k2 = std::numeric_limits<double>::infinity(), best_k3 = 0;
    for (int corner = 0; corner < 3; ++corner) {
      const auto x0 = coords(tri[corner]), x1 = coords(tri[(corner + 1) % 3]),
                 x2 = coords(tri[(corner + 2) % 3]);
      const double a[2] = {x1[0] - x0[0], x1[1] - x0[1]}, b[2] = {x2[0] - x0[0], x2[1] - x0[1]};
      const double det = std::abs(a[0] * b[1] - a[1] * b[0]);
      if (!(det > 0)) continue;  // a zero-area triangle covers no pixel
      const double la = std::abs(a[0]) + std::abs(a[1]), lb = std::abs(b[0]) + std::abs(b[1]);
      const double rho = la * lb / det;
      if (rho * (la + lb) / 2 < best_k2) best_k2 = rho * (la + lb) / 2, best_k3 = rho * la * lb / 4;
    }
    if (best_k2 == std::numeric_limits<double>::infinity()) continue;
    k[0] = std::max(k[0], best_k2);
    k[1] = std::max(k[1], best_k3);
  }
  return k;
}

std::vector<TangentPlaneCoefficient> tangentPlaneCoefficients(
    techniques::PatchDomain domain, const techniques::PatchCullBounds& bounds,
    const mesh::Vec3d& origin) {
  if (bounds.bezier_net.empty()) return {};
  const int degree = bounds.bezier_degree;
  const bool quad = domain == techniques::PatchDomain::kQuad;
  const size_t expected = netSize(quad, degree);
  if (degree < 1 || bounds.bezier_net.size() != expected) {
    throw std::invalid_argument("tangent plane: a degree-" + std::to_string(degree) + " " +
                                (quad ? "quad" : "triangle") + " net needs " +
                                std::to_string(expected) + " points, the patch gives " +
                                std::to_string(bounds.bezier_net.size()));
  }
  std::vector<mesh::Vec3d> relative = bounds.bezier_net;
  for (mesh::Vec3d& p : relative) p = p - origin;
  return quad ? quadCoefficients(relative, degree, bounds.bezier_mirrored)
              : triangleCoefficients(relative, degree, bounds.bezier_mirrored);
}

}  // namespace tb::lod
