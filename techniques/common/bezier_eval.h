// Bicubic Bézier evaluation in the operation orders of seed 000 ("ベジェパッチの計算"),
// templated on the scalar so the same order runs in double, in float (as the TES does;
// shaders/common/bezier.glsl is its twin) and with CountingScalar. Control points
// b[i + 4 j], i along u; rows first, then the column. The four orders and their instruction
// counts: docs/derivations/acc_gregory.md. The symmetric forms give bitwise-equal points for t
// and 1 - t with mirrored control points, which makes shared edges watertight
// (docs/ARCHITECTURE.md §5 rule 2).
#pragma once

#include <array>
#include <cmath>

#include "core/mesh/vec.h"
#include "techniques/counting_scalar.h"

namespace tb::techniques {

// kSymmetricNoFmaImprecise is kSymmetricNoFma written without `precise` in the shader:
// the same arithmetic on the CPU, but the GPU compiler may reassociate it (NIR folds
// constants such as the 3 of B1/B2), which is what breaks bitwise symmetry there.
enum class BezierOrder {
  kAsymmetric,
  kSymmetricNoFma,
  kSymmetricFma,
  kSymmetricEdges,
  kSymmetricNoFmaImprecise,
};

// The shader's fma(a, b, c) as the device executes it. Measured on lavapipe (Mesa
// 22.3.6): GLSL fma() on `precise` values runs as a multiply and an add, each rounded
// (0 ulp from the capture this way, up to 8 ulp with std::fma), so the float twin
// rounds twice too. The build targets generic x86-64, which has no FMA for GCC to
// contract this into; tests/techniques/acc_gpu_test.cpp would catch a change.
// Double keeps one rounding. CountingScalar counts one mul and one add.
inline float fusedMulAdd(float a, float b, float c) { return a * b + c; }
inline double fusedMulAdd(double a, double b, double c) { return std::fma(a, b, c); }
template <class T>
CountingScalar<T> fusedMulAdd(CountingScalar<T> a, CountingScalar<T> b, CountingScalar<T> c) {
  return a * b + c;
}

template <class T>
mesh::Vec3T<T> fusedMulAdd(const mesh::Vec3T<T>& p, T w, const mesh::Vec3T<T>& c) {
  return {fusedMulAdd(p.x, w, c.x), fusedMulAdd(p.y, w, c.y), fusedMulAdd(p.z, w, c.z)};
}

// Cubic Bernstein basis at t with s = 1 - t; B1 and B2 (and B0 and B3) are mirrored
// formulas, so basis(1 - t) is basis(t) reversed, bit for bit.
template <class T>
std::array<T, 4> cubicBasis(T t) {
  const T s = T(1) - t;
  return {s * s * s, T(3) * s * s * t, T(3) * t * t * s, t * t * t};
}

template <class T>
std::array<T, 3> quadraticBasis(T t) {
  const T s = T(1) - t;
  return {s * s, T(2) * s * t, t * t};
}

enum class BezierSum { kChain, kSymmetricNoFma, kSymmetricFma };

template <class T>
mesh::Vec3T<T> bezierSum4(const mesh::Vec3T<T>& p0, const mesh::Vec3T<T>& p1,
                          const mesh::Vec3T<T>& p2, const mesh::Vec3T<T>& p3,
                          const std::array<T, 4>& b, BezierSum sum) {
  switch (sum) {
    case BezierSum::kChain:
      return fusedMulAdd(p3, b[3], fusedMulAdd(p2, b[2], fusedMulAdd(p1, b[1], p0 * b[0])));
    case BezierSum::kSymmetricNoFma:
      return (p0 * b[0] + p1 * b[1]) + (p3 * b[3] + p2 * b[2]);
    case BezierSum::kSymmetricFma:
      break;
  }
  return fusedMulAdd(p1, b[1], p0 * b[0]) + fusedMulAdd(p2, b[2], p3 * b[3]);
}

template <class T>
mesh::Vec3T<T> evaluateBicubic(const std::array<mesh::Vec3T<T>, 16>& b, T u, T v,
                               BezierOrder order) {
  const std::array<T, 4> bu = cubicBasis(u);
  const std::array<T, 4> bv = cubicBasis(v);
  BezierSum outer_rows = BezierSum::kSymmetricFma, inner_rows = BezierSum::kSymmetricFma;
  BezierSum column = BezierSum::kSymmetricFma;
  switch (order) {
    case BezierOrder::kAsymmetric:
      outer_rows = inner_rows = column = BezierSum::kChain;
      break;
    case BezierOrder::kSymmetricNoFma:
    case BezierOrder::kSymmetricNoFmaImprecise:
      outer_rows = inner_rows = column = BezierSum::kSymmetricNoFma;
      break;
    case BezierOrder::kSymmetricFma:
      break;
    case BezierOrder::kSymmetricEdges:
      inner_rows = BezierSum::kChain;
      break;
  }
  std::array<mesh::Vec3T<T>, 4> w;
  for (int j = 0; j < 4; ++j) {
    w[j] = bezierSum4(b[4 * j], b[4 * j + 1], b[4 * j + 2], b[4 * j + 3], bu,
                      j == 0 || j == 3 ? outer_rows : inner_rows);
  }
  return bezierSum4(w[0], w[1], w[2], w[3], bv, column);
}

// evaluateBicubic in double with its fusedMulAdd as the processor's FMA instruction where
// it has one: the build targets generic x86-64, where std::fma is a call into libm (a
// tenth of a production run's adaptivity time). Bit for bit the same point: fma rounds once
// either way, and nothing else is contracted, whatever the including file's flags
// (fp-contract=off here). Internal linkage: no two files' copies can stand in for each other.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
namespace {
[[gnu::target("fma"), gnu::flatten, gnu::optimize("fp-contract=off")]] inline mesh::Vec3d
evaluateBicubicWithFma(const std::array<mesh::Vec3d, 16>& b, double u, double v,
                       BezierOrder order) {
  return evaluateBicubic(b, u, v, order);
}
inline mesh::Vec3d evaluateBicubicFast(const std::array<mesh::Vec3d, 16>& b, double u, double v,
                                       BezierOrder order) {
  static const bool has_fma = __builtin_cpu_supports("fma");
  return has_fma ? evaluateBicubicWithFma(b, u, v, order) : evaluateBicubic(b, u, v, order);
}
}  // namespace
#else
inline mesh::Vec3d evaluateBicubicFast(const std::array<mesh::Vec3d, 16>& b, double u, double v,
                                       BezierOrder order) {
  return evaluateBicubic(b, u, v, order);
}
#endif

// A tensor-product Bézier patch of degree (3 in one parameter, 2 in the other) as
// used for tangent fields: tu[i + 3 j] (degree 2 in u, 3 in v) and tv[i + 4 j]
// (degree 3 in u, 2 in v). Plain sums: normals need no bitwise symmetry.
template <class T>
mesh::Vec3T<T> evaluateTangentU(const std::array<mesh::Vec3T<T>, 12>& tu, T u, T v) {
  const std::array<T, 3> qu = quadraticBasis(u);
  const std::array<T, 4> bv = cubicBasis(v);
  mesh::Vec3T<T> result{};
  for (int j = 0; j < 4; ++j) {
    const mesh::Vec3T<T> row = tu[3 * j] * qu[0] + tu[3 * j + 1] * qu[1] + tu[3 * j + 2] * qu[2];
    result = j == 0 ? row * bv[0] : result + row * bv[j];
  }
  return result;
}

template <class T>
mesh::Vec3T<T> evaluateTangentV(const std::array<mesh::Vec3T<T>, 12>& tv, T u, T v) {
  const std::array<T, 4> bu = cubicBasis(u);
  const std::array<T, 3> qv = quadraticBasis(v);
  mesh::Vec3T<T> result{};
  for (int j = 0; j < 3; ++j) {
    const mesh::Vec3T<T> row =
        tv[4 * j] * bu[0] + tv[4 * j + 1] * bu[1] + tv[4 * j + 2] * bu[2] + tv[4 * j + 3] * bu[3];
    result = j == 0 ? row * qv[0] : result + row * qv[j];
  }
  return result;
}

// Derivative patches of a bicubic (the tangent fields of the geometry itself):
// tu = 3 (b[i+1, j] - b[i, j]), tv = 3 (b[i, j+1] - b[i, j]).
template <class T>
void bicubicDerivativePatches(const std::array<mesh::Vec3T<T>, 16>& b,
                              std::array<mesh::Vec3T<T>, 12>& tu,
                              std::array<mesh::Vec3T<T>, 12>& tv) {
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 3; ++i) tu[3 * j + i] = (b[4 * j + i + 1] - b[4 * j + i]) * T(3);
  }
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) tv[4 * j + i] = (b[4 * (j + 1) + i] - b[4 * j + i]) * T(3);
  }
}

}  // namespace tb::techniques
