// SurfacePatches::curvatureBounds (CurvatureBounds, techniques/technique.h) of every registered
// surface technique, every non-control variant, on curved bundled assets, against the
// technique's own double evaluate(), sampled with the exact identities of
// tests/curvature_samples.h (each sample at most the supremum it samples).
// Each holds exactly for any S that is C^1 with bounded second derivatives on the stencil;
// the tolerance covers only double rounding (relative 1e-6 of the bound plus 1e-7 of the
// hull's box diagonal). Stencil points sit away from the dyadic lines of osd_adaptive's
// sub-patches (the sub-patch seams, where a Gregory end cap's first derivative may jump).
// A control: the same check against halved bounds fails on some patch of every technique
// with bounds, so the check is seen to catch a bound that is too small. Prints the median
// over patches of max sampled / bound per technique and variant (the tightness).
#include "techniques/common/curvature_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "reference/triangle_mesh_ref.h"
#include "techniques/registry.h"
#include "tests/curvature_samples.h"
#include "tests/test_support.h"

namespace tb::curvature_bounds_test {
namespace {

using techniques::DomainCoord;
using techniques::PatchDomain;
using testing::Sampled;
using testing::sampleQuad;
using testing::sampleTriangle;

// Extraordinary vertices (cube, pawn, xord_interior; valence 3 to 6), quads with triangles
// (pyramid, gregory_test5: gregory_acc's triangle patches), boundaries and corners
// (edgecorner, gregory_test5: osd_adaptive's boundary patches), a regular torus, triangles
// for pn_triangles and phong (torus, pawn, icosahedron).
const std::vector<std::string> kAssets = {"opensubdiv/catmark_cube.obj",
                                          "opensubdiv/catmark_pyramid.obj",
                                          "opensubdiv/catmark_edgecorner.obj",
                                          "opensubdiv/catmark_gregory_test5.obj",
                                          "opensubdiv/catmark_xord_interior.obj",
                                          "opensubdiv/catmark_pawn.obj",
                                          "opensubdiv/catmark_torus.obj",
                                          "tessbench/tri_torus.obj",
                                          "tessbench/tri_pawn.obj",
                                          "opensubdiv/loop_icosahedron.obj"};

constexpr double kRelative = 1e-6;
constexpr double kAbsolute = 1e-7;  // of the hull's box diagonal

using tb::testing::loadAsset;
using tb::testing::surfaceTechniques;

std::array<double, 7> boundsOf(const techniques::CurvatureBounds& b) {
  return {b.uu, b.uv, b.vv, b.edge[0], b.edge[1], b.edge[2], b.edge[3]};
}

// How many of the 7 quantities exceed `scale` times their bound beyond rounding.
int violations(const Sampled& sampled, const std::array<double, 7>& bound, double scale,
               double size) {
  int count = 0;
  for (size_t k = 0; k < 7; ++k) {
    const double allowed = scale * bound[k] * (1 + kRelative) + kAbsolute * size;
    if (sampled[k] > allowed) ++count;
  }
  return count;
}

struct Tally {
  size_t patches = 0, bounded = 0, curved = 0, failing = 0, failing_halved = 0;
  // Edges two patches share; of them, those with different edge[] on one curve (a failure)
  // and those whose two curves differ (a crack of the technique, no fault of the bound).
  size_t shared_edges = 0, disagreeing_edges = 0, cracked_edges = 0;
  double seconds = 0;  // in curvatureBounds() (once per patch, in checkSharedEdges)
  std::vector<double> ratio, edge_ratio;  // per bounded patch: max sampled / bound
};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// The control-mesh corners at the ends of edge e of a patch, in CurvatureBounds' edge order
// (quad: u = 0 joins corners 0 and 3, v = 0 corners 0 and 1, u = 1 corners 1 and 2, v = 1
// corners 3 and 2; triangle: u = 0 joins corners 1 and 2, v = 0 2 and 0, w = 0 0 and 1).
std::pair<uint32_t, uint32_t> edgeCorners(const std::array<uint32_t, 4>& c, bool quad, int e) {
  static constexpr int kQuad[4][2] = {{0, 3}, {0, 1}, {1, 2}, {3, 2}};
  static constexpr int kTriangle[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  const int* ends = quad ? kQuad[e] : kTriangle[e];
  const uint32_t a = c[size_t(ends[0])], b = c[size_t(ends[1])];
  return {std::min(a, b), std::max(a, b)};
}

// The point at t of edge e of a patch (t from its first corner, as the samplers above).
mesh::Vec3d edgePoint(const techniques::SurfacePatches& s, size_t p, int e, double t) {
  if (s.patchDomain(p) == PatchDomain::kQuad) {
    static constexpr double kQuad[4][4] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {1, 0, 0, 1}, {0, 1, 1, 0}};
    const double* q = kQuad[e];
    return s.evaluate(p, {q[0] + q[2] * t, q[1] + q[3] * t, 0}).position;
  }
  static constexpr double kTriangle[3][4] = {{0, 1, 0, -1}, {0, 0, 1, 0}, {1, 0, -1, 1}};
  const double* q = kTriangle[e];
  const double u = q[0] + q[2] * t, v = q[1] + q[3] * t;
  return s.evaluate(p, {u, v, 1 - u - v}).position;
}

// True when the two patches' curves on their shared edge differ (a crack in the surface
// itself): compared at t = 0.3 and 0.5, either direction.
bool curvesDiffer(const techniques::SurfacePatches& s, size_t p, int e, size_t q, int f) {
  const double size = ref::boundingBoxDiagonal(s.curvatureBounds(p)->hull);
  const double tolerance = 1e-9 * size;
  const mesh::Vec3d a = edgePoint(s, p, e, 0.3);
  const double apart =
      std::min(length(a - edgePoint(s, q, f, 0.3)), length(a - edgePoint(s, q, f, 0.7)));
  return apart > tolerance || length(edgePoint(s, p, e, 0.5) - edgePoint(s, q, f, 0.5)) > tolerance;
}

// Two patches that share an edge get the same edge[] bound up to rounding (the struct's
// promise, which keeps the error_bound policy's levels of a shared edge equal) within 1e-9
// of the larger bound or of the edge's extent (per-patch nets round differently), unless
// their edge curves differ (pn_triangles/rounding scales an edge's bulge by each face's
// own corner normals, so split normals give two curves).
void checkSharedEdges(const techniques::SurfacePatches& s, const std::string& what, Tally& tally) {
  struct Seen {
    size_t patch;
    int edge;
    double bound;
  };
  std::map<std::pair<uint32_t, uint32_t>, Seen> first;
  for (size_t p = 0; p < s.patchCount(); ++p) {
    const auto start = std::chrono::steady_clock::now();
    const std::optional<techniques::CurvatureBounds> bounds = s.curvatureBounds(p);
    tally.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!bounds) continue;
    const bool quad = s.patchDomain(p) == PatchDomain::kQuad;
    for (int e = 0; e < (quad ? 4 : 3); ++e) {
      const double bound = bounds->edge[size_t(e)];
      const auto [it, fresh] =
          first.try_emplace(edgeCorners(s.patchCorners(p), quad, e), Seen{p, e, bound});
      if (fresh) continue;
      ++tally.shared_edges;
      // Rounding: of the larger bound, or of the edge's extent where the edge is straight.
      const double scale = std::max({std::abs(bound), std::abs(it->second.bound),
                                     ref::boundingBoxDiagonal(bounds->edge_hull[size_t(e)])});
      if (std::abs(bound - it->second.bound) <= 1e-9 * scale) continue;
      if (curvesDiffer(s, p, e, it->second.patch, it->second.edge)) {
        ++tally.cracked_edges;
      } else {
        ++tally.disagreeing_edges;
        ADD_FAILURE() << what << ": patches " << it->second.patch << " and " << p
                      << " share an edge curve but bound it by " << it->second.bound << " and "
                      << bound;
      }
    }
  }
}

void checkSurface(const techniques::SurfacePatches& s, const std::string& what, Tally& tally) {
  checkSharedEdges(s, what, tally);
  for (size_t p = 0; p < s.patchCount(); ++p) {
    ++tally.patches;
    const std::optional<techniques::CurvatureBounds> bounds = s.curvatureBounds(p);
    if (!bounds) continue;
    ++tally.bounded;
    ASSERT_FALSE(bounds->hull.empty()) << what << " patch " << p;
    const bool quad = s.patchDomain(p) == PatchDomain::kQuad;
    for (int e = 0; e < (quad ? 4 : 3); ++e) {
      ASSERT_FALSE(bounds->edge_hull[size_t(e)].empty()) << what << " patch " << p << " edge " << e;
    }
    if (!quad) {
      EXPECT_EQ(bounds->edge[3], 0.0) << what << " patch " << p;
    }
    const double size = ref::boundingBoxDiagonal(bounds->hull);
    const Sampled sampled = quad ? sampleQuad(s, p) : sampleTriangle(s, p);
    const std::array<double, 7> bound = boundsOf(*bounds);
    const int failed = violations(sampled, bound, 1.0, size);
    EXPECT_EQ(failed, 0) << what << " patch " << p << ": sampled uu " << sampled[0] << " uv "
                         << sampled[1] << " vv " << sampled[2] << " edges " << sampled[3] << " "
                         << sampled[4] << " " << sampled[5] << " " << sampled[6] << "; bounds "
                         << bound[0] << " " << bound[1] << " " << bound[2] << " edges " << bound[3]
                         << " " << bound[4] << " " << bound[5] << " " << bound[6];
    tally.failing += failed > 0;
    tally.curved += *std::max_element(bound.begin(), bound.end()) > kAbsolute * size;
    tally.failing_halved += violations(sampled, bound, 0.5, size) > 0;
    double ratio = 0, edge_ratio = 0;
    for (size_t k = 0; k < 7; ++k) {
      if (bound[k] <= kAbsolute * size) continue;
      (k < 3 ? ratio : edge_ratio) = std::max(k < 3 ? ratio : edge_ratio, sampled[k] / bound[k]);
    }
    tally.ratio.push_back(ratio);
    tally.edge_ratio.push_back(edge_ratio);
  }
}

TEST(CurvatureBounds, SampledSecondDifferencesStayWithinTheBoundsOfEveryTechnique) {
  std::map<std::string, Tally> by_variant;
  for (const std::string& name : kAssets) {
    const mesh::Mesh mesh = loadAsset(name);
    for (const techniques::Technique* t : surfaceTechniques()) {
      if (!t->checkSupport(mesh).empty()) continue;
      for (const techniques::VariantInfo& v : t->variants()) {
        if (!v.control.empty()) continue;
        const std::string id = t->info().id + "/" + v.name;
        checkSurface(*techniques::buildSurface(*t, mesh, v), id + " on " + name, by_variant[id]);
      }
    }
  }
  for (const auto& [id, tally] : by_variant) {
    std::printf(
        "%-32s patches %5zu, bounded %5zu; median max sampled / bound: surface %.3f, edges "
        "%.3f; failing %zu, failing with halved bounds %zu; shared edges %zu, disagreeing %zu, "
        "cracked %zu; %.2f us per patch\n",
        id.c_str(), tally.patches, tally.bounded, median(tally.ratio), median(tally.edge_ratio),
        tally.failing, tally.failing_halved, tally.shared_edges, tally.disagreeing_edges,
        tally.cracked_edges, 1e6 * tally.seconds / double(std::max<size_t>(tally.patches, 1)));
    // The control: halved bounds are caught on some patch wherever there are bounds above
    // rounding (phong/alpha0 is the flat triangle: every bound and sample 0).
    if (tally.curved > 0) {
      EXPECT_GT(tally.failing_halved, 0u) << id;
    }
  }
  // Every technique's default variant gives bounds for every patch (the displaced variants
  // and phong's per-edge variant give none by design).
  for (const techniques::Technique* t : surfaceTechniques()) {
    const std::string id = t->info().id + "/" + t->variants()[0].name;
    ASSERT_TRUE(by_variant.count(id)) << id;
    EXPECT_EQ(by_variant[id].bounded, by_variant[id].patches) << id;
    EXPECT_GT(by_variant[id].patches, 20u) << id;
  }
}

// The Gregory blend functions g_c = B_c (a - b) / (a + b) of curvature_bounds.h, sampled with
// the same second-difference identities: within every constant they are given, and close to
// it where the constant is the supremum (so a constant read from the wrong quadrant or corner
// shows).
double cubicBernstein(int i, double x) {
  const double y = 1 - x;
  const double b[4] = {y * y * y, 3 * x * y * y, 3 * x * x * y, x * x * x};
  return b[i];
}

double quadBlend(int c, double u, double v) {
  static constexpr int kColumn[4] = {1, 2, 2, 1}, kRow[4] = {1, 1, 2, 2};
  const double a[4] = {u, v, 1 - u, 1 - v}, b[4] = {v, 1 - u, 1 - v, u};
  const double t = (a[c] - b[c]) / (a[c] + b[c]);
  return cubicBernstein(kColumn[c], u) * cubicBernstein(kRow[c], v) * t;
}

double triangleBlend(int c, double u, double v) {
  const double w = 1 - u - v;
  const double x[3] = {u, v, w};
  const double a = x[(c + 1) % 3], b = x[(c + 2) % 3];  // (v, w), (w, u), (u, v)
  return 12 * x[c] * x[c] * a * b * (a - b) / (a + b);
}

// Largest |second differences| of f over the points (u, v) of `points` (step h).
template <class F>
std::array<double, 3> blendSecondDifferences(const F& f,
                                             const std::vector<std::array<double, 2>>& points,
                                             double h) {
  std::array<double, 3> m{};
  const double inv = 1 / (h * h);
  for (const auto& [u, v] : points) {
    const double c = f(u, v);
    m[0] = std::max(m[0], std::abs(f(u + h, v) - 2 * c + f(u - h, v)) * inv);
    m[1] = std::max(
        m[1], std::abs(f(u + h, v + h) - f(u + h, v - h) - f(u - h, v + h) + f(u - h, v - h)) *
                  (0.25 * inv));
    m[2] = std::max(m[2], std::abs(f(u, v + h) - 2 * c + f(u, v - h)) * inv);
  }
  return m;
}

TEST(CurvatureBounds, GregoryBlendConstantsBoundTheBlendFunctions) {
  constexpr double kH = 1e-4;
  constexpr int kGrid = 60;
  const double tolerance = 1e-5;  // rounding of the differences of O(1) values over h^2
  for (int qa = 0; qa < 2; ++qa) {
    for (int qb = 0; qb < 2; ++qb) {
      std::vector<std::array<double, 2>> points;  // inside the quadrant by 2 h
      for (int j = 0; j <= kGrid; ++j) {
        for (int i = 0; i <= kGrid; ++i) {
          points.push_back({0.5 * qa + 2 * kH + (0.5 - 4 * kH) * i / kGrid,
                            0.5 * qb + 2 * kH + (0.5 - 4 * kH) * j / kGrid});
        }
      }
      for (int c = 0; c < 4; ++c) {
        const auto m = blendSecondDifferences(
            [c](double u, double v) { return quadBlend(c, u, v); }, points, kH);
        // Corner c reads g_0's quadrant reflected in u (corners 1, 2) and v (2, 3).
        const int ra = qa ^ (c == 1 || c == 2), rb = qb ^ (c >= 2);
        const auto& k = techniques::kGregoryQuadBlend[size_t(ra)][size_t(rb)];
        const std::string what = "quad corner " + std::to_string(c) + " quadrant " +
                                 std::to_string(qa) + std::to_string(qb);
        EXPECT_LE(m[0], k.uu + tolerance) << what;
        EXPECT_LE(m[1], k.uv + tolerance) << what;
        EXPECT_LE(m[2], k.vv + tolerance) << what;
        std::printf("%s: sampled / constant uu %.3f uv %.3f vv %.3f\n", what.c_str(), m[0] / k.uu,
                    m[1] / k.uv, m[2] / k.vv);
        // The constants are suprema (limits at corner 0 in quadrant 00) or within 0.93 of
        // them (the far quadrant's), so the grid comes close.
        EXPECT_GT(m[0], 0.9 * k.uu) << what;
        EXPECT_GT(m[1], 0.9 * k.uv) << what;
        EXPECT_GT(m[2], 0.9 * k.vv) << what;
      }
    }
  }
  // The triangle's regions (u >= 1/2, v >= 1/2, w >= 1/2, the middle), each sampled on a
  // grid 3 h inside the triangle (so up to its corners) and 2 h inside the region's cuts.
  const auto inRegion = [&](int region, double u, double v) {
    const double w = 1 - u - v, m = 2 * kH;
    if (region < 3) return std::array<double, 3>{u, v, w}[size_t(region)] >= 0.5 + m;
    return u <= 0.5 - m && v <= 0.5 - m && w <= 0.5 - m;
  };
  for (int region = 0; region < 4; ++region) {
    std::vector<std::array<double, 2>> points;
    constexpr int kSteps = 4 * kGrid;
    for (int j = 0; j <= kSteps; ++j) {
      for (int i = 0; i + j <= kSteps; ++i) {
        const double u = 3 * kH + (1 - 9 * kH) * i / kSteps, v = 3 * kH + (1 - 9 * kH) * j / kSteps;
        if (inRegion(region, u, v)) points.push_back({u, v});
      }
    }
    ASSERT_GT(points.size(), 100u);
    for (int c = 0; c < 3; ++c) {
      const auto m = blendSecondDifferences(
          [c](double u, double v) { return triangleBlend(c, u, v); }, points, kH);
      const auto& k = techniques::kGregoryTriangleBlend[size_t(c)][size_t(region)];
      const std::string what =
          "triangle corner " + std::to_string(c) + " region " + std::to_string(region);
      EXPECT_LE(m[0], k.uu + tolerance) << what;
      EXPECT_LE(m[1], k.uv + tolerance) << what;
      EXPECT_LE(m[2], k.vv + tolerance) << what;
      // The suprema on the corner's own region are limits at the corner (a grid 3 h from it
      // comes within a few percent); elsewhere the Bernstein bounds are within 0.85 of the
      // largest value sampled finely (the script's), and this grid within 0.8 of them.
      const double close = region == c ? 0.9 : 0.8;
      EXPECT_GT(m[0], close * k.uu) << what;
      EXPECT_GT(m[1], close * k.uv) << what;
      EXPECT_GT(m[2], close * k.vv) << what;
      // The control: the whole domain's constants (the corner's own region's), which the
      // bound used on every region before, are caught by the same closeness check away
      // from the corner.
      const auto& whole = techniques::kGregoryTriangleBlend[size_t(c)][size_t(c)];
      if (region != c) {
        EXPECT_TRUE(m[0] <= close * whole.uu || m[1] <= close * whole.uv ||
                    m[2] <= close * whole.vv)
            << what;
      }
      std::printf("%s: sampled / constant uu %.3f uv %.3f vv %.3f\n", what.c_str(), m[0] / k.uu,
                  m[1] / k.uv, m[2] / k.vv);
    }
  }
}

}  // namespace
}  // namespace tb::curvature_bounds_test
