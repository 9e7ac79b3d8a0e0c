// SurfacePatches::cullBounds (PatchCullBounds, techniques/technique.h) of every registered
// surface technique, every variant, on bundled assets, against the technique's own double
// evaluate():
//  1. hull: every surface point of a 9 x 9 (quad) or matching triangle lattice lies in the
//     hull's axis-aligned box and below the hull's support function in random directions;
//  2. generators: the geometric normal p_1 x p_2 (central differences of evaluate()
//     positions along the domain directions in the face's winding) lies in the generators'
//     cone, checked with separating directions d (min over generators of d·g > 0 must give
//     d·n >= 0): the generators' mean direction, random directions, and random directions
//     near the mean;
//  3. orientation: on closed convex meshes the summed unit generators point outward;
//  4. the checks reject a flipped generator set and a shrunken hull.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "reference/triangle_mesh_ref.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// Quads with extraordinary vertices, boundaries, quads and triangles (gregory_acc triangle
// patches), n-gons (gregory_acc refines once), triangles only, split normals.
const std::vector<std::string> kAssets = {"opensubdiv/catmark_cube.obj",
                                          "opensubdiv/catmark_torus.obj",
                                          "opensubdiv/catmark_pyramid.obj",
                                          "opensubdiv/catmark_nonquads.obj",
                                          "opensubdiv/catmark_gregory_test2.obj",
                                          "opensubdiv/catmark_gregory_test5.obj",
                                          "opensubdiv/catmark_edgecorner.obj",
                                          "opensubdiv/catmark_xord_interior.obj",
                                          "opensubdiv/catmark_toroidal_tet.obj",
                                          "opensubdiv/catmark_pawn.obj",
                                          "opensubdiv/loop_cube.obj",
                                          "opensubdiv/loop_icosahedron.obj",
                                          "opensubdiv/loop_triangle_edgecorner.obj",
                                          "tessbench/tri_torus.obj",
                                          "tessbench/tri_pawn.obj",
                                          "tessbench/flat_cube.obj"};

constexpr int kLattice = 8;              // segments per domain edge
constexpr double kHullTolerance = 1e-9;  // of the hull's box diagonal
constexpr double kConeTolerance = 1e-6;  // of |n|, for d·n with unit d
constexpr double kStep = 1e-5;           // central-difference step, domain units
constexpr double kMargin = 1e-4;         // lattice pulled inside the domain by this
constexpr double kDegenerate = 1e-8;     // |n| below this times the box diagonal squared

using testing::loadAsset;
using testing::surfaceTechniques;
using testing::technique;

std::vector<techniques::DomainCoord> lattice(techniques::PatchDomain domain) {
  std::vector<techniques::DomainCoord> coords;
  for (int j = 0; j <= kLattice; ++j) {
    for (int i = 0; i <= (domain == techniques::PatchDomain::kQuad ? kLattice : kLattice - j);
         ++i) {
      const double u = double(i) / kLattice, v = double(j) / kLattice;
      coords.push_back({u, v, domain == techniques::PatchDomain::kQuad ? 0.0 : 1 - u - v});
    }
  }
  return coords;
}

mesh::Vec3d randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n(0, 1);
  return normalize(mesh::Vec3d{n(rng), n(rng), n(rng)});
}

// The geometric normal at `c`, moved kMargin inside the domain: p_u x p_v on a quad; on a
// triangle the derivatives toward corners 1 and 2 (weights of corners 0, 1, 2 = c).
mesh::Vec3d differenceNormal(const techniques::SurfacePatches& s, size_t patch,
                             techniques::DomainCoord c) {
  const auto at = [&](const techniques::DomainCoord& d) { return s.evaluate(patch, d).position; };
  const double h = kStep, scale = 0.5 / kStep;
  if (s.patchDomain(patch) == techniques::PatchDomain::kQuad) {
    for (int k = 0; k < 2; ++k) c[k] = kMargin + (1 - 2 * kMargin) * c[k];
    const mesh::Vec3d du = (at({c[0] + h, c[1], 0}) - at({c[0] - h, c[1], 0})) * scale;
    const mesh::Vec3d dv = (at({c[0], c[1] + h, 0}) - at({c[0], c[1] - h, 0})) * scale;
    return cross(du, dv);
  }
  for (int k = 0; k < 3; ++k) c[k] = kMargin + (1 - 3 * kMargin) * c[k];
  const mesh::Vec3d d1 = (at({c[0] - h, c[1] + h, c[2]}) - at({c[0] + h, c[1] - h, c[2]})) * scale;
  const mesh::Vec3d d2 = (at({c[0] - h, c[1], c[2] + h}) - at({c[0] + h, c[1], c[2] - h})) * scale;
  return cross(d1, d2);
}

// How many of `points` lie outside `hull`'s box or above its support function in 16
// random directions.
size_t hullViolations(const std::vector<mesh::Vec3d>& hull, const std::vector<mesh::Vec3d>& points,
                      std::mt19937& rng) {
  const double tolerance = kHullTolerance * std::max(ref::boundingBoxDiagonal(hull), 1e-300);
  mesh::Vec3d lo = hull[0], hi = lo;
  for (const mesh::Vec3d& p : hull) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  std::vector<mesh::Vec3d> directions;
  for (int k = 0; k < 16; ++k) directions.push_back(randomUnit(rng));
  size_t violations = 0;
  for (const mesh::Vec3d& p : points) {
    bool inside = true;
    for (int k = 0; k < 3; ++k)
      inside = inside && p[k] >= lo[k] - tolerance && p[k] <= hi[k] + tolerance;
    for (const mesh::Vec3d& d : directions) {
      double support = -1e300;
      for (const mesh::Vec3d& h : hull) support = std::max(support, dot(d, h));
      inside = inside && dot(d, p) <= support + tolerance;
    }
    if (!inside) ++violations;
  }
  return violations;
}

struct ConeResult {
  size_t separating = 0;  // directions with min_g d·g > 0 (those that test anything)
  size_t violations = 0;  // (direction, normal) pairs with d·n < -tol |n|
  bool pointed = false;   // the mean direction separates: the cone is less than a half-space
};

mesh::Vec3d meanDirection(const std::vector<mesh::Vec3d>& generators) {
  mesh::Vec3d sum{};
  for (const mesh::Vec3d& g : generators) sum = sum + normalize(g);
  return normalize(sum);
}

ConeResult checkCone(const std::vector<mesh::Vec3d>& generators,
                     const std::vector<mesh::Vec3d>& normals, std::mt19937& rng) {
  ConeResult result;
  const mesh::Vec3d mean = meanDirection(generators);
  std::vector<mesh::Vec3d> directions = {mean};
  for (int k = 0; k < 30; ++k) directions.push_back(randomUnit(rng));
  for (int k = 0; k < 30; ++k) directions.push_back(normalize(mean + randomUnit(rng) * 0.6));
  for (size_t k = 0; k < directions.size(); ++k) {
    const mesh::Vec3d& d = directions[k];
    double lowest = 1e300;
    for (const mesh::Vec3d& g : generators) lowest = std::min(lowest, dot(d, normalize(g)));
    if (!(lowest > 0)) continue;
    ++result.separating;
    if (k == 0) result.pointed = true;
    for (const mesh::Vec3d& n : normals) {
      if (dot(d, n) < -kConeTolerance * length(n)) ++result.violations;
    }
  }
  return result;
}

// Surface points and geometric normals of one patch on the lattice.
struct PatchSamples {
  std::vector<mesh::Vec3d> points, normals;
};

PatchSamples sample(const techniques::SurfacePatches& s, size_t patch, double size) {
  PatchSamples samples;
  for (const techniques::DomainCoord& c : lattice(s.patchDomain(patch))) {
    samples.points.push_back(s.evaluate(patch, c).position);
    const mesh::Vec3d n = differenceNormal(s, patch, c);
    if (length(n) > kDegenerate * size * size) samples.normals.push_back(n);
  }
  return samples;
}

// Half the opening of a cone: the largest angle between the generators' mean direction and
// a generator, in degrees.
double halfOpeningDegrees(const std::vector<mesh::Vec3d>& generators) {
  const mesh::Vec3d mean = meanDirection(generators);
  double lowest = 1;
  for (const mesh::Vec3d& g : generators) lowest = std::min(lowest, dot(mean, normalize(g)));
  return std::acos(std::clamp(lowest, -1.0, 1.0)) * 180 / 3.141592653589793;
}

struct Tally {
  size_t patches = 0, with_generators = 0, pointed = 0, separating = 0;
  double opening_sum = 0;  // of halfOpeningDegrees over the pointed cones
  std::map<std::string, std::pair<size_t, size_t>> generator_range;  // per domain: min, max
};

// Every patch; under a sanitizer every 4th (the same code on a quarter of the samples).
void checkSurface(const techniques::SurfacePatches& s, const std::string& what, Tally& tally) {
  std::mt19937 rng(1);
  for (size_t p = 0; p < s.patchCount(); p += testing::sweepStride(4)) {
    const std::optional<techniques::PatchCullBounds> bounds = s.cullBounds(p);
    ASSERT_TRUE(bounds.has_value()) << what << " patch " << p;
    ASSERT_FALSE(bounds->hull.empty()) << what << " patch " << p;
    const double size = ref::boundingBoxDiagonal(bounds->hull);
    const PatchSamples samples = sample(s, p, size);
    EXPECT_EQ(hullViolations(bounds->hull, samples.points, rng), 0u) << what << " patch " << p;
    ++tally.patches;
    const std::vector<mesh::Vec3d>& generators = bounds->normal_generators;
    if (generators.empty()) continue;
    ++tally.with_generators;
    for (const mesh::Vec3d& g : generators)
      ASSERT_FALSE(g == mesh::Vec3d{}) << what << " patch " << p;
    auto [range, fresh] = tally.generator_range.try_emplace(toString(s.patchDomain(p)),
                                                            generators.size(), generators.size());
    range->second.first = std::min(range->second.first, generators.size());
    range->second.second = std::max(range->second.second, generators.size());
    const ConeResult cone = checkCone(generators, samples.normals, rng);
    EXPECT_EQ(cone.violations, 0u) << what << " patch " << p;
    tally.pointed += cone.pointed ? 1 : 0;
    if (cone.pointed) tally.opening_sum += halfOpeningDegrees(generators);
    tally.separating += cone.separating;
  }
}

TEST(PatchCullBounds, HullAndNormalConeContainEveryPatchOfEveryTechnique) {
  std::map<std::string, Tally> by_technique;
  for (const std::string& name : kAssets) {
    const mesh::Mesh mesh = loadAsset(name);
    for (const techniques::Technique* t : surfaceTechniques()) {
      if (!t->checkSupport(mesh).empty()) continue;
      for (const techniques::VariantInfo& v : t->variants()) {
        const std::string what = t->info().id + "/" + v.name + " on " + name;
        checkSurface(*techniques::buildSurface(*t, mesh, v), what,
                     by_technique[t->info().id + "/" + v.name]);
      }
    }
  }
  for (const auto& [id, tally] : by_technique) {
    std::printf(
        "%-29s patches %5zu, with generators %5zu, pointed %5zu (mean half-opening "
        "%4.1f deg), separating directions %6zu;",
        id.c_str(), tally.patches, tally.with_generators, tally.pointed,
        tally.pointed > 0 ? tally.opening_sum / double(tally.pointed) : 0.0, tally.separating);
    for (const auto& [domain, range] : tally.generator_range) {
      std::printf(" %s %zu..%zu", domain.c_str(), range.first, range.second);
    }
    std::printf("\n");
  }
  // Every technique's default variant was checked on several assets, and the cone check
  // had directions to test with.
  for (const techniques::Technique* t : surfaceTechniques()) {
    const std::string id = t->info().id + "/" + t->variants()[0].name;
    ASSERT_TRUE(by_technique.count(id)) << id;
    EXPECT_GT(by_technique[id].patches, 50u / testing::sweepStride(4)) << id;
    // A technique that gives no normal bound (osd_adaptive: hull only) has no cone to test.
    if (by_technique[id].with_generators > 0) {
      EXPECT_GT(by_technique[id].pointed, by_technique[id].with_generators / 2) << id;
    }
  }
  // Tightness: every acc and gregory_acc cone on these assets is less than a half-space
  // (a looser Gregory bound, e.g. the cone of all pairwise crosses of the derivatives'
  // generators, is a whole space on most irregular and all triangle patches).
  for (const char* id : {"acc/default", "gregory_acc/edge_symmetric", "gregory_acc/quads_only"}) {
    EXPECT_EQ(by_technique[id].pointed, by_technique[id].with_generators) << id;
  }
}

// Closed convex meshes seen from outside: the summed unit generators of every patch point
// away from the mesh centre.
TEST(PatchCullBounds, GeneratorsFaceOutwardOnClosedConvexMeshes) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"acc", "opensubdiv/catmark_cube.obj"},
      {"gregory_acc", "opensubdiv/catmark_cube.obj"},
      {"gregory_acc", "opensubdiv/loop_icosahedron.obj"},  // triangle Gregory patches
      {"pn_triangles", "opensubdiv/loop_cube.obj"},
      {"pn_triangles", "opensubdiv/loop_icosahedron.obj"},
      {"phong", "opensubdiv/loop_cube.obj"},
      {"phong", "opensubdiv/loop_icosahedron.obj"}};
  for (const auto& [id, name] : cases) {
    const techniques::Technique& t = technique(id);
    const techniques::BuiltSurface s =
        techniques::buildSurface(t, loadAsset(name), t.variants()[0]);
    mesh::Vec3d centre{};
    for (const mesh::Vec3d& p : s->controlMesh().positions) centre = centre + p;
    centre = centre * (1.0 / double(s->controlMesh().positions.size()));
    for (size_t p = 0; p < s->patchCount(); ++p) {
      const bool quad = s->patchDomain(p) == techniques::PatchDomain::kQuad;
      const techniques::DomainCoord middle = quad ? techniques::DomainCoord{0.5, 0.5, 0}
                                                  : techniques::DomainCoord{1. / 3, 1. / 3, 1. / 3};
      const mesh::Vec3d outward = s->evaluate(p, middle).position - centre;
      const std::vector<mesh::Vec3d> generators = s->cullBounds(p)->normal_generators;
      ASSERT_FALSE(generators.empty()) << id << " on " << name << " patch " << p;
      EXPECT_GT(dot(meanDirection(generators), normalize(outward)), 0.5)
          << id << " on " << name << " patch " << p;
    }
  }
}

// The checks above can fail: negated generators leave the normals outside the cone, and a
// hull shrunk toward its centroid leaves surface points outside.
TEST(PatchCullBounds, TheChecksRejectFlippedGeneratorsAndAShrunkenHull) {
  for (const char* id : {"acc", "gregory_acc", "pn_triangles", "phong"}) {
    const techniques::Technique& t = technique(id);
    const bool quads = std::string(id) == "acc" || std::string(id) == "gregory_acc";
    const techniques::BuiltSurface s = techniques::buildSurface(
        t, loadAsset(quads ? "opensubdiv/catmark_torus.obj" : "tessbench/tri_torus.obj"),
        t.variants()[0]);
    std::mt19937 rng(2);
    size_t flipped_rejected = 0, shrunk_rejected = 0;
    for (size_t p = 0; p < s->patchCount(); ++p) {
      techniques::PatchCullBounds bounds = *s->cullBounds(p);
      const double size = ref::boundingBoxDiagonal(bounds.hull);
      const PatchSamples samples = sample(*s, p, size);
      ASSERT_EQ(checkCone(bounds.normal_generators, samples.normals, rng).violations, 0u);
      for (mesh::Vec3d& g : bounds.normal_generators) g = mesh::Vec3d{} - g;
      if (checkCone(bounds.normal_generators, samples.normals, rng).violations > 0)
        ++flipped_rejected;
      mesh::Vec3d centroid{};
      for (const mesh::Vec3d& h : bounds.hull) centroid = centroid + h;
      centroid = centroid * (1.0 / double(bounds.hull.size()));
      for (mesh::Vec3d& h : bounds.hull) h = centroid + (h - centroid) * 0.5;
      if (hullViolations(bounds.hull, samples.points, rng) > 0) ++shrunk_rejected;
    }
    EXPECT_EQ(flipped_rejected, s->patchCount()) << id;
    EXPECT_EQ(shrunk_rejected, s->patchCount()) << id;
  }
}

}  // namespace
}  // namespace tb
