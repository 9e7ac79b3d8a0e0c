// ACC control points (Loop & Schaefer, "Approximating Catmull-Clark Subdivision Surfaces
// with Bicubic Patches", ACM TOG 27(1), 2008: geometry masks §3.1, tangent patches §3.2),
// templated on the scalar so the same operation order runs in double, in float (as
// shaders/acc/acc.tesc) and with CountingScalar. The masks, boundary and crease rules and the
// cross-tangent construction: docs/derivations/acc_gregory.md. Sums run in the stored ring
// order, so every patch sharing a control point computes it bit for bit the same way
// (docs/ARCHITECTURE.md §5 rule 1).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "core/mesh/vec.h"
#include "techniques/common/bezier_eval.h"
#include "techniques/common/quad_ring.h"

namespace tb::acc {

// Stencil weights of one corner vertex kind (valence, boundary); the GPU reads the
// same values as float from the stencil table (kCornerWeightFloats per corner).
struct CornerWeights {
  double cv = 0, ce = 0, cf = 0;          // corner point: v, each e_i, each f_i
  double ev = 0, ee = 0, ea = 0, ef = 0;  // edge point: v, e_i, e_{i±1}, f_{i-1} and f_i
  double iv = 0, ie = 0, iff = 0;         // interior point: v, e_i and e_{i+1}, f_i
  double bv = 0, be = 0;                  // boundary edge point: v, e
  double cosine = 0;                      // c = cos(2π/n) on the interior, 0 on a boundary
};
inline constexpr int kCornerWeightFloats = 16;

// `corner`: a boundary or sector corner the limit interpolates (weights v alone).
CornerWeights cornerWeights(uint32_t valence, bool boundary, bool corner);
// Limit tangent mask of an interior vertex of valence n: α[0..n-1] on e_j, then
// β[0..n-1] on f_j, for the tangent along e_0.
std::vector<double> tangentMask(uint32_t valence);

// Control point j = i + 4 k (i along u): which patch corner owns it and its role.
enum class PointRole : uint8_t { kCorner, kEdgeNext, kEdgePrev, kInterior };
struct PointOwner {
  uint8_t corner;
  PointRole role;
};
inline constexpr std::array<PointOwner, 16> kPointOwner = {{
    {0, PointRole::kCorner},
    {0, PointRole::kEdgeNext},
    {1, PointRole::kEdgePrev},
    {1, PointRole::kCorner},
    {0, PointRole::kEdgePrev},
    {0, PointRole::kInterior},
    {1, PointRole::kInterior},
    {1, PointRole::kEdgeNext},
    {3, PointRole::kEdgeNext},
    {3, PointRole::kInterior},
    {2, PointRole::kInterior},
    {2, PointRole::kEdgePrev},
    {3, PointRole::kCorner},
    {3, PointRole::kEdgePrev},
    {2, PointRole::kEdgeNext},
    {2, PointRole::kCorner},
}};
// Grid index of each patch corner's corner point.
inline constexpr std::array<int, 4> kCornerPoint = {0, 3, 15, 12};

template <class T>
struct AccControlPoints {
  std::array<mesh::Vec3T<T>, 16> b;   // geometry patch, b[i + 4 j]
  std::array<mesh::Vec3T<T>, 12> tu;  // ∂/∂u tangent patch, tu[i + 3 j], degree 2 in u
  std::array<mesh::Vec3T<T>, 12> tv;  // ∂/∂v tangent patch, tv[i + 4 j], degree 2 in v
};

// One patch corner as the builder sees it.
struct PatchCorner {
  uint32_t vertex;
  uint32_t slot;  // ring slot of the face at this vertex (QuadRings::face_slots)
  const CornerWeights* weights;
  const std::vector<double>* mask;  // tangent mask of the valence; null on a boundary
};

template <class T, class Position>
mesh::Vec3T<T> accControlPoint(const techniques::QuadRings& rings, const PatchCorner& c,
                               PointRole role, const Position& position) {
  const techniques::VertexRing& ring = rings.rings[c.vertex];
  const CornerWeights& w = *c.weights;
  const uint32_t n = ring.valence;
  const mesh::Vec3T<T> v = position(c.vertex);
  const auto e = [&](uint32_t i) { return position(rings.e(c.vertex, i)); };
  const auto f = [&](uint32_t i) { return position(rings.f(c.vertex, i)); };
  switch (role) {
    case PointRole::kCorner: {
      mesh::Vec3T<T> acc = v * T(w.cv);
      // (e_0 + e_{n-1}) adds commutatively: the two sectors of a crease vertex list its
      // crease neighbours in opposite orders and still compute the same bits.
      if (ring.boundary) return acc + (e(0) + e(n - 1)) * T(w.ce);
      for (uint32_t i = 0; i < n; ++i) acc = acc + e(i) * T(w.ce) + f(i) * T(w.cf);
      return acc;
    }
    case PointRole::kEdgeNext:
    case PointRole::kEdgePrev: {
      const uint32_t i = c.slot + (role == PointRole::kEdgePrev ? 1 : 0);
      if (ring.boundary && (i == 0 || i == n - 1)) return v * T(w.bv) + e(i) * T(w.be);
      const uint32_t prev = i + n - 1;  // modulo n in the ring accessors
      return v * T(w.ev) + e(i) * T(w.ee) + e(prev) * T(w.ea) + e(i + 1) * T(w.ea) +
             f(prev) * T(w.ef) + f(i) * T(w.ef);
    }
    case PointRole::kInterior:
      break;
  }
  return v * T(w.iv) + e(c.slot) * T(w.ie) + e(c.slot + 1) * T(w.ie) + f(c.slot) * T(w.iff);
}

// Limit tangent of an interior corner along e_i (mask rotated by i).
template <class T, class Position>
mesh::Vec3T<T> accCornerTangent(const techniques::QuadRings& rings, const PatchCorner& c,
                                uint32_t i, const Position& position) {
  const uint32_t n = rings.rings[c.vertex].valence;
  const std::vector<double>& mask = *c.mask;
  mesh::Vec3T<T> acc{};
  for (uint32_t j = 0; j < n; ++j) {
    const uint32_t r = (j + n - i % n) % n;
    acc = acc + position(rings.e(c.vertex, j)) * T(mask[r]) +
          position(rings.f(c.vertex, j)) * T(mask[n + r]);
  }
  return acc;
}

// Cross tangents next to the corners of the edge A -> B (see the header comment).
template <class T>
void accCrossTangents(T c_a, T c_b, const mesh::Vec3T<T>& a0, const mesh::Vec3T<T>& a1,
                      const mesh::Vec3T<T>& a2, const mesh::Vec3T<T>& d1, const mesh::Vec3T<T>& d2,
                      mesh::Vec3T<T>& x1, mesh::Vec3T<T>& x2) {
  const T third = T(1) / T(3);
  x1 = (a1 * (T(2) * c_a) - a0 * c_b) * third + d1;
  x2 = (a2 * c_a - a1 * (T(2) * c_b)) * third + d2;
}

template <class T, class Position>
AccControlPoints<T> accControlPoints(const techniques::QuadRings& rings,
                                     const std::array<PatchCorner, 4>& corners,
                                     bool tangent_patches, const Position& position) {
  AccControlPoints<T> p;
  for (int j = 0; j < 16; ++j) {
    p.b[j] =
        accControlPoint<T>(rings, corners[kPointOwner[j].corner], kPointOwner[j].role, position);
  }
  techniques::bicubicDerivativePatches(p.b, p.tu, p.tv);
  if (!tangent_patches) return p;
  const auto& b = p.b;
  auto& tu = p.tu;
  auto& tv = p.tv;
  // Corner tangents along the next (e_slot) and previous (e_slot+1) edges.
  std::array<mesh::Vec3T<T>, 4> next, prev;
  std::array<T, 4> c;
  for (int k = 0; k < 4; ++k) {
    const PatchCorner& corner = corners[k];
    c[k] = T(corner.weights->cosine);
    if (corner.mask == nullptr) continue;  // boundary: the geometry tangents stay
    next[k] = accCornerTangent<T>(rings, corner, corner.slot, position);
    prev[k] = accCornerTangent<T>(rings, corner, corner.slot + 1, position);
  }
  const T zero(0);
  const auto set = [&](int k, mesh::Vec3T<T>& slot, const mesh::Vec3T<T>& value, bool negate) {
    if (corners[k].mask != nullptr)
      slot = negate ? mesh::Vec3T<T>{zero, zero, zero} - value : value;
  };
  set(0, tu[0], next[0], false);
  set(0, tv[0], prev[0], false);
  set(1, tu[2], prev[1], true);
  set(1, tv[3], next[1], false);
  set(2, tu[11], next[2], true);
  set(2, tv[11], prev[2], true);
  set(3, tu[9], prev[3], false);
  set(3, tv[8], next[3], true);
  const T three(3);
  mesh::Vec3T<T> x1, x2;
  // v = 0, c0 -> c1: inward cross tangent is tv.
  accCrossTangents(c[0], c[1], tu[0], tu[1], tu[2], (b[5] - b[1]) * three, (b[6] - b[2]) * three,
                   x1, x2);
  tv[1] = x1;
  tv[2] = x2;
  // u = 1, c1 -> c2: inward is -tu.
  accCrossTangents(c[1], c[2], tv[3], tv[7], tv[11], (b[6] - b[7]) * three, (b[10] - b[11]) * three,
                   x1, x2);
  tu[5] = mesh::Vec3T<T>{zero, zero, zero} - x1;
  tu[8] = mesh::Vec3T<T>{zero, zero, zero} - x2;
  // v = 1, c3 -> c2: inward is -tv.
  accCrossTangents(c[3], c[2], tu[9], tu[10], tu[11], (b[9] - b[13]) * three,
                   (b[10] - b[14]) * three, x1, x2);
  tv[9] = mesh::Vec3T<T>{zero, zero, zero} - x1;
  tv[10] = mesh::Vec3T<T>{zero, zero, zero} - x2;
  // u = 0, c0 -> c3: inward is tu.
  accCrossTangents(c[0], c[3], tv[0], tv[4], tv[8], (b[5] - b[4]) * three, (b[9] - b[8]) * three,
                   x1, x2);
  tu[3] = x1;
  tu[6] = x2;
  return p;
}

}  // namespace tb::acc
