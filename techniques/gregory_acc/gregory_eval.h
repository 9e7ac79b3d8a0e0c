// Evaluation of a quad Gregory patch from its 20 control points, templated on the scalar
// so one operation order runs in double, in float (the TES order, shaders/gregory_acc/
// gregory_acc.tese) and with CountingScalar. Keep the two in step.
#pragma once

#include <array>

#include "core/mesh/vec.h"
#include "techniques/gregory_acc/gregory_stencils.h"

namespace tb::gregory_acc {

template <class T>
using GregoryPoints = std::array<mesh::Vec3T<T>, kPointsPerPatch>;  // corner * 5 + Slot

template <class T>
struct GregoryPoint {
  mesh::Vec3T<T> position;
  mesh::Vec3T<T> normal;
};

// Position and the two tangents whose cross product is the normal: ∂/∂u and ∂/∂v on a
// quad; on a triangle the derivatives towards corners 1 and 2 (see the triangle below).
// Linear in the control points for a fixed domain point (gregory_batch.h relies on it).
template <class T>
struct GregoryFrame {
  mesh::Vec3T<T> position;
  mesh::Vec3T<T> tangent_u;
  mesh::Vec3T<T> tangent_v;
};

// One control point as its stencil's weighted sum, ascending vertex index, from zero
// (the TCS loop).
template <class T, class PositionAt>
mesh::Vec3T<T> stencilPoint(const GregoryStencils& stencils, uint32_t s, const PositionAt& position,
                            const auto& weight) {
  mesh::Vec3T<T> sum{T(0), T(0), T(0)};
  for (uint32_t k = stencils.offsets[s]; k < stencils.offsets[s + 1]; ++k) {
    sum = sum + position(stencils.indices[k]) * weight(k);
  }
  return sum;
}

// Half of a cubic edge curve: p x^3 + e 3 x^2 y. The curve from A (t = 0) to B is
// half(A, EA, s, t) + half(B, EB, t, s) with s = 1 - t: swapping the ends swaps the two
// halves and float addition commutes, so both patches of an edge get the same bits
// (seed 000's symmetric evaluation; docs/ARCHITECTURE.md §5 rule 2).
template <class T>
mesh::Vec3T<T> halfEdge(const mesh::Vec3T<T>& p, const mesh::Vec3T<T>& e, T x, T y) {
  const T x2 = x * x;
  return p * (x2 * x) + e * ((T(3) * x2) * y);
}

template <class T>
mesh::Vec3T<T> symmetricEdge(const mesh::Vec3T<T>& a, const mesh::Vec3T<T>& ea,
                             const mesh::Vec3T<T>& eb, const mesh::Vec3T<T>& b, T t) {
  const T s = T(1) - t;
  return halfEdge(a, ea, s, t) + halfEdge(b, eb, t, s);
}

// Cubic Bernstein basis at t (bit for bit the b of the overload below).
template <class T>
std::array<T, 4> bernstein3(T t) {
  const T s = T(1) - t;
  return {s * s * s, T(3) * s * s * t, T(3) * s * t * t, t * t * t};
}
// Cubic Bernstein basis and derivative at t.
template <class T>
void bernstein3(T t, std::array<T, 4>& b, std::array<T, 4>& d) {
  const T s = T(1) - t;
  b = {s * s * s, T(3) * s * s * t, T(3) * s * t * t, t * t * t};
  d = {T(-3) * s * s, T(3) * s * (s - T(2) * t), T(3) * t * (T(2) * s - t), T(3) * t * t};
}

// The blended face point alone (bit for bit the q of the overload below).
template <class T>
mesh::Vec3T<T> blendFace(const mesh::Vec3T<T>& fp, const mesh::Vec3T<T>& fm, T a, T b) {
  const T sum = a + b;
  if (sum == T(0)) return (fp + fm) * T(0.5);
  return (fp * a + fm * b) * (T(1) / sum);
}
// Rationally blended face point (a Fp + b Fm) / (a + b) and its derivatives, given the
// derivatives of a and b (Loop et al. 2009 eq. 2). At the patch corner a + b = 0: the
// point's Bernstein weight and derivative weight are zero there, so the mean is used.
template <class T>
void blendFace(const mesh::Vec3T<T>& fp, const mesh::Vec3T<T>& fm, T a, T b, T a_u, T b_u, T a_v,
               T b_v, mesh::Vec3T<T>& q, mesh::Vec3T<T>& q_u, mesh::Vec3T<T>& q_v) {
  const T sum = a + b;
  if (sum == T(0)) {
    q = (fp + fm) * T(0.5);
    q_u = q_v = mesh::Vec3T<T>{T(0), T(0), T(0)};
    return;
  }
  const T inv = T(1) / sum;
  q = (fp * a + fm * b) * inv;
  const mesh::Vec3T<T> diff = (fp - fm) * (inv * inv);
  q_u = diff * (a_u * b - b_u * a);
  q_v = diff * (a_v * b - b_v * a);
}

// The quad's 4x4 Bézier net q[j][i] (row j along v, column i along u) outside its four
// interior points: the corner and edge points, copied. kQuadNetInterior names the interior
// slots: net slot (j, i) holds the blend of corner c's Fp and Fm.
struct QuadNetInterior {
  int row, column;
  uint32_t corner;
};
inline constexpr std::array<QuadNetInterior, 4> kQuadNetInterior{
    {{1, 1, 0}, {1, 2, 1}, {2, 2, 2}, {2, 1, 3}}};

template <class T>
void setQuadBoundaryNet(const GregoryPoints<T>& cp,
                        std::array<std::array<mesh::Vec3T<T>, 4>, 4>& q) {
  auto at = [&cp](uint32_t corner, Slot slot) { return cp[corner * 5 + slot]; };
  q[0] = {at(0, kP), at(0, kEp), at(1, kEm), at(1, kP)};
  q[3] = {at(3, kP), at(3, kEm), at(2, kEp), at(2, kP)};
  q[1][0] = at(0, kEm);
  q[1][3] = at(1, kEp);
  q[2][0] = at(3, kEp);
  q[2][3] = at(2, kEm);
}

// Position and tangents at (u, v). `symmetric_edges`: points on the domain boundary
// come from the shared edge curve alone, evaluated symmetrically.
template <class T>
GregoryFrame<T> evaluateGregoryFrame(const GregoryPoints<T>& cp, T u, T v, bool symmetric_edges) {
  const T one(1), zero(0);
  const T iu = one - u, iv = one - v;
  // 4x4 Bézier net q[j][i] (row j along v, column i along u); the four interior points
  // depend on (u, v). Corner c's interior point blends Fp (next to the edge to corner
  // c + 1) and Fm (next to the edge to corner c - 1), each taking over on its own edge.
  std::array<std::array<mesh::Vec3T<T>, 4>, 4> q;
  std::array<std::array<mesh::Vec3T<T>, 4>, 4> q_u{}, q_v{};
  auto at = [&cp](uint32_t corner, Slot slot) { return cp[corner * 5 + slot]; };
  setQuadBoundaryNet(cp, q);
  blendFace(at(0, kFp), at(0, kFm), u, v, one, zero, zero, one, q[1][1], q_u[1][1], q_v[1][1]);
  blendFace(at(1, kFp), at(1, kFm), v, iu, zero, -one, one, zero, q[1][2], q_u[1][2], q_v[1][2]);
  blendFace(at(2, kFp), at(2, kFm), iu, iv, -one, zero, zero, -one, q[2][2], q_u[2][2], q_v[2][2]);
  blendFace(at(3, kFp), at(3, kFm), iv, u, zero, one, -one, zero, q[2][1], q_u[2][1], q_v[2][1]);

  std::array<T, 4> bu, du, bv, dv;
  bernstein3(u, bu, du);
  bernstein3(v, bv, dv);
  mesh::Vec3T<T> position{zero, zero, zero}, tangent_u = position, tangent_v = position;
  for (int j = 0; j < 4; ++j) {
    mesh::Vec3T<T> row{zero, zero, zero}, row_u = row;
    for (int i = 0; i < 4; ++i) {
      row = row + q[j][i] * bu[i];
      row_u = row_u + q[j][i] * du[i];
    }
    position = position + row * bv[j];
    tangent_u = tangent_u + row_u * bv[j];
    tangent_v = tangent_v + row * dv[j];
  }
  // Derivatives of the blended interior points.
  for (int j = 1; j < 3; ++j) {
    for (int i = 1; i < 3; ++i) {
      const T w = bu[i] * bv[j];
      tangent_u = tangent_u + q_u[j][i] * w;
      tangent_v = tangent_v + q_v[j][i] * w;
    }
  }
  if (symmetric_edges) {
    if (v == zero) {
      position = symmetricEdge(at(0, kP), at(0, kEp), at(1, kEm), at(1, kP), u);
    } else if (u == one) {
      position = symmetricEdge(at(1, kP), at(1, kEp), at(2, kEm), at(2, kP), v);
    } else if (v == one) {
      position = symmetricEdge(at(3, kP), at(3, kEm), at(2, kEp), at(2, kP), u);
    } else if (u == zero) {
      position = symmetricEdge(at(0, kP), at(0, kEm), at(3, kEp), at(3, kP), v);
    }
  }
  return {position, tangent_u, tangent_v};
}

// The position alone at (u, v): evaluateGregoryFrame's, bit for bit (the same operations in
// the same order), without the tangents.
template <class T>
mesh::Vec3T<T> evaluateGregoryPosition(const GregoryPoints<T>& cp, T u, T v, bool symmetric_edges) {
  const T one(1), zero(0);
  const T iu = one - u, iv = one - v;
  auto at = [&cp](uint32_t corner, Slot slot) { return cp[corner * 5 + slot]; };
  if (symmetric_edges) {
    if (v == zero) return symmetricEdge(at(0, kP), at(0, kEp), at(1, kEm), at(1, kP), u);
    if (u == one) return symmetricEdge(at(1, kP), at(1, kEp), at(2, kEm), at(2, kP), v);
    if (v == one) return symmetricEdge(at(3, kP), at(3, kEm), at(2, kEp), at(2, kP), u);
    if (u == zero) return symmetricEdge(at(0, kP), at(0, kEm), at(3, kEp), at(3, kP), v);
  }
  std::array<std::array<mesh::Vec3T<T>, 4>, 4> q;
  setQuadBoundaryNet(cp, q);
  q[1][1] = blendFace(at(0, kFp), at(0, kFm), u, v);
  q[1][2] = blendFace(at(1, kFp), at(1, kFm), v, iu);
  q[2][2] = blendFace(at(2, kFp), at(2, kFm), iu, iv);
  q[2][1] = blendFace(at(3, kFp), at(3, kFm), iv, u);
  const std::array<T, 4> bu = bernstein3(u), bv = bernstein3(v);
  mesh::Vec3T<T> position{zero, zero, zero};
  for (int j = 0; j < 4; ++j) {
    mesh::Vec3T<T> row{zero, zero, zero};
    for (int i = 0; i < 4; ++i) row = row + q[j][i] * bu[i];
    position = position + row * bv[j];
  }
  return position;
}

// Position and unit normal at (u, v).
template <class T>
GregoryPoint<T> evaluateGregory(const GregoryPoints<T>& cp, T u, T v, bool symmetric_edges) {
  const GregoryFrame<T> frame = evaluateGregoryFrame(cp, u, v, symmetric_edges);
  return {frame.position, normalize(cross(frame.tangent_u, frame.tangent_v))};
}

// The quartic triangle's control net, points b_ijk (i + j + k = 4, i the power of the
// corner-0 coordinate u, j of v, k of w) in the fixed order of kQuarticNet, and the
// cubic net (i + j + k = 3) its derivatives use.
struct NetIndex {
  int i, j, k;
  int multinomial;  // 4! / (i! j! k!), or 3! / (i! j! k!) in the cubic net
};
inline constexpr std::array<NetIndex, 15> kQuarticNet{{
    {4, 0, 0, 1},
    {3, 1, 0, 4},
    {3, 0, 1, 4},
    {2, 2, 0, 6},
    {2, 1, 1, 12},
    {2, 0, 2, 6},
    {1, 3, 0, 4},
    {1, 2, 1, 12},
    {1, 1, 2, 12},
    {1, 0, 3, 4},
    {0, 4, 0, 1},
    {0, 3, 1, 4},
    {0, 2, 2, 6},
    {0, 1, 3, 4},
    {0, 0, 4, 1},
}};
inline constexpr std::array<NetIndex, 10> kCubicNet{{
    {3, 0, 0, 1},
    {2, 1, 0, 3},
    {2, 0, 1, 3},
    {1, 2, 0, 3},
    {1, 1, 1, 6},
    {1, 0, 2, 3},
    {0, 3, 0, 1},
    {0, 2, 1, 3},
    {0, 1, 2, 3},
    {0, 0, 3, 1},
}};
// Position of b_ijk in kQuarticNet (rows of descending i, each by descending j).
constexpr int quarticSlot(int i, int j, int k) {
  (void)k;
  return (4 - i) * (5 - i) / 2 + (4 - i - j);
}
static_assert(quarticSlot(2, 1, 1) == 4 && quarticSlot(0, 0, 4) == 14 && quarticSlot(1, 0, 3) == 9);

// The quartic triangle's net outside its three interior points: the corners and the cubic
// boundary curves P_c, Ep_c, Em_{c+1}, P_{c+1} degree-raised, e.g. b310 = (P0 + 3 Ep0) / 4,
// b220 = (Ep0 + Em1) / 2. kTriangleNetInterior: slot b_ijk holds the blend of corner c's
// Fp and Fm.
struct TriangleNetInterior {
  int i, j, k;
  uint32_t corner;
};
inline constexpr std::array<TriangleNetInterior, 3> kTriangleNetInterior{
    {{2, 1, 1, 0}, {1, 2, 1, 1}, {1, 1, 2, 2}}};

template <class T>
void setTriangleBoundaryNet(const GregoryPoints<T>& cp, std::array<mesh::Vec3T<T>, 15>& b) {
  const T quarter(0.25), half(0.5), three(3);
  auto at = [&cp](uint32_t corner, Slot slot) { return cp[corner * 5 + slot]; };
  auto set = [&b](int i, int j, int k, const mesh::Vec3T<T>& p) { b[quarticSlot(i, j, k)] = p; };
  auto nearEnd = [&](const mesh::Vec3T<T>& p, const mesh::Vec3T<T>& e) {
    return (p + e * three) * quarter;
  };
  set(4, 0, 0, at(0, kP));
  set(0, 4, 0, at(1, kP));
  set(0, 0, 4, at(2, kP));
  set(3, 1, 0, nearEnd(at(0, kP), at(0, kEp)));  // edge 0: corner 0 -> 1 (w = 0)
  set(2, 2, 0, (at(0, kEp) + at(1, kEm)) * half);
  set(1, 3, 0, nearEnd(at(1, kP), at(1, kEm)));
  set(0, 3, 1, nearEnd(at(1, kP), at(1, kEp)));  // edge 1: corner 1 -> 2 (u = 0)
  set(0, 2, 2, (at(1, kEp) + at(2, kEm)) * half);
  set(0, 1, 3, nearEnd(at(2, kP), at(2, kEm)));
  set(1, 0, 3, nearEnd(at(2, kP), at(2, kEp)));  // edge 2: corner 2 -> 0 (v = 0)
  set(2, 0, 2, (at(2, kEp) + at(0, kEm)) * half);
  set(3, 0, 1, nearEnd(at(0, kP), at(0, kEm)));
}

// Triangle Gregory patch (Loop et al. 2009: cubic boundaries, quartic interior) at
// barycentric (u, v, w) = gl_TessCoord: position and the derivatives toward corners 1 and 2
// (S_v - S_u, S_w - S_u), whose cross is the normal. The net, with interior points
// b211 = (v Fp0 + w Fm0) / (v + w) and its rotations: docs/derivations/acc_gregory.md.
// `symmetric_edges`: boundary points from the cubic edge curve alone, with a quad's
// operations (symmetricEdge), so a shared edge gives the same bits from both sides.
template <class T>
GregoryFrame<T> evaluateGregoryTriangleFrame(const GregoryPoints<T>& cp, T u, T v, T w,
                                             bool symmetric_edges) {
  const T one(1), zero(0), four(4);
  auto at = [&cp](uint32_t corner, Slot slot) { return cp[corner * 5 + slot]; };
  std::array<mesh::Vec3T<T>, 15> b;
  auto set = [&b](int i, int j, int k, const mesh::Vec3T<T>& p) { b[quarticSlot(i, j, k)] = p; };
  setTriangleBoundaryNet(cp, b);
  // Interior blends with derivatives along a = d/dv - d/du and c = d/dw - d/du.
  mesh::Vec3T<T> q_a[3], q_c[3];
  mesh::Vec3T<T> q0, q1, q2;
  blendFace(at(0, kFp), at(0, kFm), v, w, one, zero, zero, one, q0, q_a[0], q_c[0]);
  blendFace(at(1, kFp), at(1, kFm), w, u, zero, -one, one, -one, q1, q_a[1], q_c[1]);
  blendFace(at(2, kFp), at(2, kFm), u, v, -one, one, -one, zero, q2, q_a[2], q_c[2]);
  set(2, 1, 1, q0);
  set(1, 2, 1, q1);
  set(1, 1, 2, q2);

  const std::array<T, 5> up{one, u, u * u, u * u * u, u * u * u * u};
  const std::array<T, 5> vp{one, v, v * v, v * v * v, v * v * v * v};
  const std::array<T, 5> wp{one, w, w * w, w * w * w, w * w * w * w};
  auto basis = [&](const NetIndex& n) {
    return T(n.multinomial) * ((up[n.i] * vp[n.j]) * wp[n.k]);
  };
  mesh::Vec3T<T> position{zero, zero, zero};
  for (const NetIndex& n : kQuarticNet)
    position = position + b[quarticSlot(n.i, n.j, n.k)] * basis(n);
  // Tangents: 4 sum over the cubic net of B3_ijk (b_i,j+1,k - b_i+1,j,k) (toward corner 1)
  // and (b_i,j,k+1 - b_i+1,j,k) (toward corner 2).
  mesh::Vec3T<T> tangent_a{zero, zero, zero}, tangent_c = tangent_a;
  for (const NetIndex& n : kCubicNet) {
    const T weight = basis(n);
    const mesh::Vec3T<T>& base = b[quarticSlot(n.i + 1, n.j, n.k)];
    tangent_a = tangent_a + (b[quarticSlot(n.i, n.j + 1, n.k)] - base) * weight;
    tangent_c = tangent_c + (b[quarticSlot(n.i, n.j, n.k + 1)] - base) * weight;
  }
  tangent_a = tangent_a * four;
  tangent_c = tangent_c * four;
  // Derivatives of the blended interior points, times their quartic Bernstein weight.
  const NetIndex interior[3] = {kQuarticNet[quarticSlot(2, 1, 1)],
                                kQuarticNet[quarticSlot(1, 2, 1)],
                                kQuarticNet[quarticSlot(1, 1, 2)]};
  for (int c = 0; c < 3; ++c) {
    const T weight = basis(interior[c]);
    tangent_a = tangent_a + q_a[c] * weight;
    tangent_c = tangent_c + q_c[c] * weight;
  }
  if (symmetric_edges) {
    if (w == zero) {
      position = symmetricEdge(at(0, kP), at(0, kEp), at(1, kEm), at(1, kP), v);
    } else if (u == zero) {
      position = symmetricEdge(at(1, kP), at(1, kEp), at(2, kEm), at(2, kP), w);
    } else if (v == zero) {
      position = symmetricEdge(at(2, kP), at(2, kEp), at(0, kEm), at(0, kP), u);
    }
  }
  return {position, tangent_a, tangent_c};
}

// The position alone at (u, v, w): evaluateGregoryTriangleFrame's, bit for bit.
template <class T>
mesh::Vec3T<T> evaluateGregoryTrianglePosition(const GregoryPoints<T>& cp, T u, T v, T w,
                                               bool symmetric_edges) {
  const T one(1), zero(0);
  auto at = [&cp](uint32_t corner, Slot slot) { return cp[corner * 5 + slot]; };
  if (symmetric_edges) {
    if (w == zero) return symmetricEdge(at(0, kP), at(0, kEp), at(1, kEm), at(1, kP), v);
    if (u == zero) return symmetricEdge(at(1, kP), at(1, kEp), at(2, kEm), at(2, kP), w);
    if (v == zero) return symmetricEdge(at(2, kP), at(2, kEp), at(0, kEm), at(0, kP), u);
  }
  std::array<mesh::Vec3T<T>, 15> b;
  setTriangleBoundaryNet(cp, b);
  b[quarticSlot(2, 1, 1)] = blendFace(at(0, kFp), at(0, kFm), v, w);
  b[quarticSlot(1, 2, 1)] = blendFace(at(1, kFp), at(1, kFm), w, u);
  b[quarticSlot(1, 1, 2)] = blendFace(at(2, kFp), at(2, kFm), u, v);
  const std::array<T, 5> up{one, u, u * u, u * u * u, u * u * u * u};
  const std::array<T, 5> vp{one, v, v * v, v * v * v, v * v * v * v};
  const std::array<T, 5> wp{one, w, w * w, w * w * w, w * w * w * w};
  mesh::Vec3T<T> position{zero, zero, zero};
  for (const NetIndex& n : kQuarticNet) {
    position = position +
               b[quarticSlot(n.i, n.j, n.k)] * (T(n.multinomial) * ((up[n.i] * vp[n.j]) * wp[n.k]));
  }
  return position;
}

template <class T>
GregoryPoint<T> evaluateGregoryTriangle(const GregoryPoints<T>& cp, T u, T v, T w,
                                        bool symmetric_edges) {
  const GregoryFrame<T> frame = evaluateGregoryTriangleFrame(cp, u, v, w, symmetric_edges);
  return {frame.position, normalize(cross(frame.tangent_u, frame.tangent_v))};
}

}  // namespace tb::gregory_acc
