// Oracle: the uniform bicubic B-spline patch, evaluated here from its basis functions
// (de Boor; the regular Catmull-Clark face is exactly this patch, Catmull & Clark
// 1978). The control mesh is a periodic grid, so every vertex has valence 4 and every
// face is regular with its full 4x4 ring.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <string>

#include "core/mesh/obj_loader.h"
#include "reference/limit_surface.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::ref {
namespace {

constexpr int kN = 7;  // grid vertices per direction (periodic in both)

// Control point (i, j) of a bumpy torus; deliberately irregular so that no symmetry
// can hide an index mistake.
mesh::Vec3d controlPoint(int i, int j) {
  const double a = 2 * 3.14159265358979 * i / kN, b = 2 * 3.14159265358979 * j / kN;
  const double r = 1 + 0.07 * std::sin(3.0 * i + 5.0 * j) + 0.03 * i;
  return {(3 + r * std::cos(b)) * std::cos(a), (3 + r * std::cos(b)) * std::sin(a),
          r * std::sin(b) + 0.05 * j};
}

int wrap(int i) { return ((i % kN) + kN) % kN; }

mesh::Mesh periodicGrid() {
  std::string text;
  for (int j = 0; j < kN; ++j) {
    for (int i = 0; i < kN; ++i) {
      const mesh::Vec3d p = controlPoint(i, j);
      text +=
          "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
  }
  // Face (i, j) has corners (i,j), (i+1,j), (i+1,j+1), (i,j+1): u along i, v along j.
  auto id = [](int i, int j) { return std::to_string(wrap(j) * kN + wrap(i) + 1); };
  for (int j = 0; j < kN; ++j) {
    for (int i = 0; i < kN; ++i) {
      text +=
          "f " + id(i, j) + " " + id(i + 1, j) + " " + id(i + 1, j + 1) + " " + id(i, j + 1) + "\n";
    }
  }
  return mesh::loadObjText(text, "periodic_grid.obj");
}

// Uniform cubic B-spline basis and its derivative at t in [0,1].
std::array<double, 4> basis(double t) {
  const double s = 1 - t;
  return {s * s * s / 6, (3 * t * t * t - 6 * t * t + 4) / 6,
          (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, t * t * t / 6};
}
std::array<double, 4> basisDerivative(double t) {
  const double s = 1 - t;
  return {-s * s / 2, (9 * t * t - 12 * t) / 6, (-9 * t * t + 6 * t + 3) / 6, t * t / 2};
}

TEST(BSplinePatch, RegularFacesEqualTheHandBuiltBicubicPatch) {
  const mesh::Mesh mesh = periodicGrid();
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  const double diagonal = boundingBoxDiagonal(mesh.positions);
  // Control points as read back from the mesh (the OBJ text rounds them).
  auto cp = [&](int i, int j) { return mesh.positions[size_t(wrap(j) * kN + wrap(i))]; };
  double worst = 0;
  for (int fj = 0; fj < kN; ++fj) {
    for (int fi = 0; fi < kN; ++fi) {
      const size_t face = size_t(fj * kN + fi);
      ASSERT_TRUE(surface.isRegular(face));
      const LimitFace prepared = surface.face(face);
      for (int a = 0; a <= 10; ++a) {
        for (int b = 0; b <= 10; ++b) {
          const double u = a / 10.0, v = b / 10.0;
          const auto bu = basis(u), bv = basis(v), du = basisDerivative(u), dv = basisDerivative(v);
          mesh::Vec3d p, pu, pv;
          for (int r = 0; r < 4; ++r) {
            for (int s = 0; s < 4; ++s) {
              const mesh::Vec3d c = cp(fi - 1 + r, fj - 1 + s);
              p = p + c * (bu[size_t(r)] * bv[size_t(s)]);
              pu = pu + c * (du[size_t(r)] * bv[size_t(s)]);
              pv = pv + c * (bu[size_t(r)] * dv[size_t(s)]);
            }
          }
          const LimitPoint bfr = prepared.evaluate(u, v);
          worst = std::max({worst, length(bfr.position - p) / diagonal,
                            length(bfr.du - pu) / diagonal, length(bfr.dv - pv) / diagonal});
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  std::cout << "max |Bfr - B-spline| / diagonal (position, du, dv): " << worst << "\n";
}

}  // namespace
}  // namespace tb::ref
