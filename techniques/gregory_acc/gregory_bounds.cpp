#include "techniques/gregory_acc/gregory_bounds.h"

#include <algorithm>
#include <array>
#include <vector>

#include "techniques/common/bernstein_poly.h"
#include "techniques/common/curvature_bounds.h"
#include "techniques/common/patch_bounds.h"

namespace tb::gregory_acc {
namespace {

// A face-point blend's a and b as functions of the domain (gregory_eval.h's blendFace
// calls): bilinear on a quad, linear on a triangle.
template <class Poly>
struct Blend {
  Poly a, b;
};

// Quad: corner 0 blends (u, v), 1 (v, 1-u), 2 (1-u, 1-v), 3 (1-v, u); bilinear() takes
// values at (0,0), (1,0), (0,1), (1,1).
std::array<Blend<techniques::QuadPoly<double>>, 4> quadBlends() {
  const techniques::QuadPoly<double> u = techniques::bilinear(0, 1, 0, 1),
                                     v = techniques::bilinear(0, 0, 1, 1);
  const techniques::QuadPoly<double> iu = techniques::bilinear(1, 0, 1, 0),
                                     iv = techniques::bilinear(1, 1, 0, 0);
  return {{{u, v}, {v, iu}, {iu, iv}, {iv, u}}};
}

// Triangle: corner 0 blends (v, w), 1 (w, u), 2 (u, v); linear() takes values at corners
// 0, 1, 2.
std::array<Blend<techniques::TrianglePoly<double>>, 3> triangleBlends() {
  const techniques::TrianglePoly<double> u = techniques::linear(1, 0, 0),
                                         v = techniques::linear(0, 1, 0),
                                         w = techniques::linear(0, 0, 1);
  return {{{v, w}, {w, u}, {u, v}}};
}

// The degree-0 polynomial 1 (`zero` gives the type and shape).
template <class Poly>
Poly constant(Poly zero) {
  zero.c.assign(1, 1.0);
  return zero;
}

template <class Poly>
Poly scaled(Poly p, double s) {
  for (auto& c : p.c) c = c * s;
  return p;
}

// Π over the blends other than `skip` (-1: none) of d², d = a + b; starts from `one`.
template <class Poly, size_t N>
Poly squaredDenominators(const std::array<Blend<Poly>, N>& blends, int skip, const Poly& one) {
  Poly product = one;
  for (size_t c = 0; c < N; ++c) {
    if (int(c) == skip) continue;
    const Poly d = blends[c].a + blends[c].b;
    product = product * (d * d);
  }
  return product;
}

// X_t = E p_t of gregory_bounds.h for the direction whose derivative `along` takes.
// `frozen` is the Bézier net with zeros in the interior slots, `basis[c]` the Bernstein
// polynomial of corner c's interior slot.
template <class ScalarPoly, class VectorPoly, size_t N, class Along>
VectorPoly scaledDerivative(const VectorPoly& frozen, const std::array<ScalarPoly, N>& basis,
                            const std::array<Blend<ScalarPoly>, N>& blends,
                            const GregoryPoints<double>& cp, const ScalarPoly& one,
                            const Along& along) {
  VectorPoly x = squaredDenominators(blends, -1, one) * along(frozen);
  for (size_t c = 0; c < N; ++c) {
    const mesh::Vec3d& fp = cp[c * 5 + kFp];
    const mesh::Vec3d& fm = cp[c * 5 + kFm];
    const ScalarPoly& a = blends[c].a;
    const ScalarPoly& b = blends[c].b;
    const ScalarPoly others = squaredDenominators(blends, int(c), one);
    const VectorPoly n = techniques::times(a, fp) + techniques::times(b, fm);
    const ScalarPoly slope = along(a) * b + scaled(along(b) * a, -1.0);  // a_t b - b_t a
    x = x + (others * (along(basis[c]) * (a + b))) * n;
    x = x + techniques::times(others * (basis[c] * slope), fp - fm);
  }
  return x;
}

// True when every corner's two face points agree within 1e-9 of the control points'
// extent (a regular neighbourhood): then the patch is the polynomial patch with their
// midpoints in its interior slots, whose net the tangent_plane policy reads. 1e-9 of the
// extent moves the surface far less than the policy's 1e-3 margin.
bool faceFree(const GregoryPoints<double>& cp, size_t corners, size_t points) {
  mesh::Vec3d lo = cp[0], hi = cp[0];
  for (size_t i = 0; i < points; ++i) {
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], cp[i][a]), hi[a] = std::max(hi[a], cp[i][a]);
  }
  const double tolerance = 1e-9 * length(hi - lo);
  for (size_t c = 0; c < corners; ++c) {
    if (!(length(cp[c * 5 + kFp] - cp[c * 5 + kFm]) <= tolerance)) return false;
  }
  return true;
}

mesh::Vec3d faceMidpoint(const GregoryPoints<double>& cp, uint32_t corner) {
  return (cp[corner * 5 + kFp] + cp[corner * 5 + kFm]) * 0.5;
}

}  // namespace

techniques::PatchCullBounds gregoryQuadCullBounds(const GregoryPoints<double>& cp) {
  std::array<std::array<mesh::Vec3d, 4>, 4> net{};
  setQuadBoundaryNet(cp, net);
  techniques::QuadPoly<mesh::Vec3d> frozen(3, 3);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) frozen.at(i, j) = net[j][i];
  }
  std::array<techniques::QuadPoly<double>, 4> basis;
  for (const QuadNetInterior& slot : kQuadNetInterior) {
    frozen.at(slot.column, slot.row) = mesh::Vec3d{};
    basis[slot.corner] = techniques::QuadPoly<double>(3, 3);
    basis[slot.corner].at(slot.column, slot.row) = 1;
  }
  const auto blends = quadBlends();
  const techniques::QuadPoly<double> one = constant(techniques::QuadPoly<double>(0, 0));
  const auto along_u = [](const auto& p) { return techniques::derivativeU(p); };
  const auto along_v = [](const auto& p) { return techniques::derivativeV(p); };
  const techniques::QuadPoly<mesh::Vec3d> x_u =
      scaledDerivative(frozen, basis, blends, cp, one, along_u);
  const techniques::QuadPoly<mesh::Vec3d> x_v =
      scaledDerivative(frozen, basis, blends, cp, one, along_v);

  techniques::PatchCullBounds bounds;
  bounds.hull.assign(cp.begin(), cp.begin() + kPointsPerPatch);
  bounds.normal_generators = techniques::withoutZeros((x_u * x_v).c);
  if (faceFree(cp, 4, kPointsPerPatch)) {
    for (const QuadNetInterior& slot : kQuadNetInterior) {
      frozen.at(slot.column, slot.row) = faceMidpoint(cp, slot.corner);
    }
    bounds.bezier_net = frozen.c;
    bounds.bezier_degree = 3;
  }
  return bounds;
}

techniques::PatchCullBounds gregoryTriangleCullBounds(const GregoryPoints<double>& cp) {
  std::array<mesh::Vec3d, 15> net{};
  setTriangleBoundaryNet(cp, net);
  // gregory_eval.h's quarticSlot and bernstein_poly.h's triangleNetSlot order b_ijk alike.
  techniques::TrianglePoly<mesh::Vec3d> frozen(4);
  frozen.c.assign(net.begin(), net.end());
  std::array<techniques::TrianglePoly<double>, 3> basis;
  for (const TriangleNetInterior& slot : kTriangleNetInterior) {
    frozen.at(slot.i, slot.j) = mesh::Vec3d{};
    basis[slot.corner] = techniques::TrianglePoly<double>(4);
    basis[slot.corner].at(slot.i, slot.j) = 1;
  }
  const auto blends = triangleBlends();
  const techniques::TrianglePoly<double> one = constant(techniques::TrianglePoly<double>(0));
  const auto toward1 = [](const auto& p) { return techniques::derivativeToward(p, 1); };
  const auto toward2 = [](const auto& p) { return techniques::derivativeToward(p, 2); };
  const techniques::TrianglePoly<mesh::Vec3d> x_1 =
      scaledDerivative(frozen, basis, blends, cp, one, toward1);
  const techniques::TrianglePoly<mesh::Vec3d> x_2 =
      scaledDerivative(frozen, basis, blends, cp, one, toward2);

  techniques::PatchCullBounds bounds;
  bounds.hull.assign(cp.begin(), cp.begin() + kPointsPerTriangle);
  bounds.normal_generators = techniques::withoutZeros((x_1 * x_2).c);
  if (faceFree(cp, 3, kPointsPerTriangle)) {
    for (const TriangleNetInterior& slot : kTriangleNetInterior) {
      frozen.at(slot.i, slot.j) = faceMidpoint(cp, slot.corner);
    }
    bounds.bezier_net = frozen.c;
    bounds.bezier_degree = 4;
  }
  return bounds;
}

namespace {

double halfGap(const GregoryPoints<double>& cp, uint32_t corner) {
  return 0.5 * length(cp[corner * 5 + kFp] - cp[corner * 5 + kFm]);
}

// The cubic edge curve from corner c to corner c + 1 (mod `corners`): P_c, Ep_c, Em_c+1, P_c+1.
std::vector<mesh::Vec3d> cubicEdge(const GregoryPoints<double>& cp, uint32_t c, uint32_t corners) {
  const uint32_t n = (c + 1) % corners;
  return {cp[c * 5 + kP], cp[c * 5 + kEp], cp[n * 5 + kEm], cp[n * 5 + kP]};
}

}  // namespace

techniques::CurvatureBounds gregoryQuadCurvatureBounds(const GregoryPoints<double>& cp) {
  std::array<std::array<mesh::Vec3d, 4>, 4> net{};
  setQuadBoundaryNet(cp, net);
  std::vector<mesh::Vec3d> flat(16);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) flat[size_t(i + 4 * j)] = net[j][i];
  }
  for (const QuadNetInterior& slot : kQuadNetInterior) {
    flat[size_t(slot.column + 4 * slot.row)] = faceMidpoint(cp, slot.corner);
  }
  // The net's boundary rows are the cubic edge curves already (edge_hull their points).
  techniques::CurvatureBounds bounds = techniques::gregoryQuadNetCurvatureBounds(
      flat, {halfGap(cp, 0), halfGap(cp, 1), halfGap(cp, 2), halfGap(cp, 3)});
  bounds.hull.assign(cp.begin(), cp.begin() + kPointsPerPatch);
  return bounds;
}

techniques::CurvatureBounds gregoryTriangleCurvatureBounds(const GregoryPoints<double>& cp) {
  std::array<mesh::Vec3d, 15> net{};
  setTriangleBoundaryNet(cp, net);
  std::vector<mesh::Vec3d> flat(net.begin(), net.end());  // quarticSlot = triangleNetSlot
  for (const TriangleNetInterior& slot : kTriangleNetInterior) {
    flat[size_t(quarticSlot(slot.i, slot.j, slot.k))] = faceMidpoint(cp, slot.corner);
  }
  techniques::CurvatureBounds bounds = techniques::triangleNetCurvatureBounds(flat, 4);
  techniques::addGregoryTriangleBlends(bounds, {halfGap(cp, 0), halfGap(cp, 1), halfGap(cp, 2)});
  // Edges u = 0 (corners 1 -> 2), v = 0 (2 -> 0), w = 0 (0 -> 1) from the cubic curves, not
  // the degree-raised quartic rows, so they equal a neighbouring quad's bound.
  const uint32_t first_corner[3] = {1, 2, 0};
  for (int e = 0; e < 3; ++e) {
    bounds.edge_hull[e] = cubicEdge(cp, first_corner[e], 3);
    bounds.edge[e] = techniques::bezierCurveSecondDerivativeBound(bounds.edge_hull[e]);
  }
  bounds.hull.assign(cp.begin(), cp.begin() + kPointsPerTriangle);
  return bounds;
}

}  // namespace tb::gregory_acc
