// Stress test of the crease preparation (techniques/common/crease_refinement.h) and the two
// techniques built on it, acc and gregory_acc, over creased shapes generated from fixed
// seeds (crease_stress_support.h: bundled meshes, refined 0 to 2 times, with random
// infinitely sharp and semi-sharp creases, corner tags, holes, boundary rules). Every shape
// either builds or is refused with an UnsupportedInput of one line; anything else (a
// std::logic_error from a construction check, a crash) fails, naming the seed and the
// shape. Oracle for the shapes that build, as the crease tests grade them: OpenSubdiv Bfr over
// the mesh the patches honour (gregory_acc_test_support.h limitMeshOf) at every patch corner
// but a dart's (both techniques keep the smooth rules there, approximate) and along every
// sharp edge between crease or corner vertices (the crease curve), within 1e-12 of the
// bounding-box diagonal. Then one small regression shape per configuration it found broken.
//
// TB_STRESS_SHAPES=N runs N shapes (default kDefaultShapes: 600, 120 under AddressSanitizer),
// TB_STRESS_FIRST_SEED=S starts at seed S (default 1):
// `TB_STRESS_SHAPES=1 TB_STRESS_FIRST_SEED=1234 crease_stress_test` reproduces shape 1234
// alone; a failing shape's OBJ is also written to a scratch folder. TB_STRESS_VERBOSE=1 prints
// each shape before it runs (a crash then names its shape) and the refusals by kind;
// TB_STRESS_OBJ=file.obj runs that file instead (the variant of gregory_acc still by seed).
#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "core/mesh/bounds.h"
#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "reference/face_domain.h"
#include "reference/limit_surface.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/registry.h"
#include "techniques/technique.h"
#include "tests/techniques/crease_stress_support.h"
#include "tests/techniques/gregory_acc_test_support.h"
#include "tests/test_support.h"

namespace tb::techniques {
namespace {

// Shapes run by default: 13 s in Release on the 2-core machine; AddressSanitizer costs about
// 7 times as much here (Bfr and the stencil maps allocate a lot), so its build runs a fifth
// (44 s for 250, 120 now; GCC defines __SANITIZE_ADDRESS__; clang has the feature).
#if defined(__SANITIZE_ADDRESS__)
constexpr uint64_t kDefaultShapes = 120;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr uint64_t kDefaultShapes = 120;
#else
constexpr uint64_t kDefaultShapes = 600;
#endif
#else
constexpr uint64_t kDefaultShapes = 600;
#endif
// |patch - Bfr limit| / bounding-box diagonal at the points limitError compares, which the
// patches reproduce by construction; the crease tests' tolerance (worst seen over 25,000
// shapes: 3.9e-15).
constexpr double kLimitTolerance = 1e-12;

uint64_t envOr(const char* name, uint64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 10) : fallback;
}

const char* kindName(SharpVertexKind kind) {
  static const char* const kNames[] = {"smooth", "dart", "crease", "corner", "cone"};
  return kNames[int(kind)];
}

// True when `mesh` has an interior vertex of valence 2 (two faces, closed around it).
// OpenSubdiv 3.5.0's Bfr crashes or overwrites memory building the irregular patches
// around some of them (a valence-2 dart; fixed in OpenSubdiv by pull requests 1336 and 1353),
// so such meshes are built and checked for their exceptions but not graded.
bool hasInteriorValence2(const mesh::Mesh& mesh) {
  const mesh::Topology topology = mesh::buildTopology(mesh);
  for (size_t v = 0; v < topology.valence.size(); ++v) {
    if (topology.valence[v] == 2 && !topology.on_boundary[v]) return true;
  }
  return false;
}

// Bfr's (u, v) of the point at fraction t along edge (c, c + 1) of a face of `size` corners
// (face_domain.h): on an N-gon's sub-faces the crease curve's halves, each at twice the
// speed (a B-spline curve's subdivision reparameterises it linearly).
mesh::Vec2d bfrEdgeUv(int size, int c, double t) {
  if (size == 4) {
    const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const double* a = corner[c];
    const double* b = corner[(c + 1) % 4];
    return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t};
  }
  const osd::Scheme scheme = osd::Scheme::kCatmullClark;
  return t <= 0.5 ? ref::subFaceToFaceUv(scheme, size, c, {2 * t, 0})
                  : ref::subFaceToFaceUv(scheme, size, (c + 1) % size, {0, 2 * (1 - t)});
}

struct LimitFigures {
  size_t corners = 0;      // patch corners compared (darts excluded)
  size_t curve_sides = 0;  // (patch, sharp edge between crease/corner vertices) pairs
  double worst = 0;        // max |patch - limit| / diagonal over both
  std::string worst_at;    // "patch 3 corner 1 (vertex 7, crease)"
  bool graded = true;      // false: Bfr cannot be trusted on this mesh (hasInteriorValence2)
};

// The patches against Bfr over the mesh they honour (the control mesh with its true remaining
// tags, or with the rounded ones where leftover semi-sharpness was rounded: limitMeshOf), as
// the crease tests (gregory_crease_test.cpp, acc_crease_test.cpp) grade them:
// - every patch corner but a dart's is the limit position (smooth: the limit mask, on the
//   refined copy next to non-quads; crease: the crease B-spline's limit point; corner: the
//   vertex);
// - along every sharp edge between crease or corner vertices the patch edge is the crease
//   curve, whatever the faces on either side.
// Vertex kinds and sharp edges: the control mesh's own preparation (nothing left to refine).
LimitFigures limitError(const SurfacePatches& patches, const std::string& technique) {
  const mesh::Mesh& control = patches.controlMesh();
  if (hasInteriorValence2(control)) {
    LimitFigures ungraded;
    ungraded.graded = false;
    return ungraded;
  }
  const CreasePreparation creases = prepareCreases(control, technique, 0);
  const ref::LimitSurface limit(gregory_acc::testing::limitMeshOf(patches, creases),
                                osd::Scheme::kCatmullClark);
  const double diagonal = mesh::diagonalOf(mesh::boundsOf(control));
  const auto crease_end = [&](uint32_t v) {
    return creases.vertex_kind[v] == SharpVertexKind::kCrease ||
           creases.vertex_kind[v] == SharpVertexKind::kCorner;
  };
  LimitFigures figures;
  const auto compare = [&](size_t p, int c, double t, const mesh::Vec3d& exact, const char* what) {
    const PatchDomain domain = patches.patchDomain(p);
    const mesh::Vec3d ours =
        patches.evaluate(p, gregory_acc::testing::edgeCoord(domain, c, t)).position;
    const double error = length(ours - exact) / diagonal;
    if (error <= figures.worst) return;
    const uint32_t v = control.facePositions(p)[size_t(c)];
    figures.worst = error;
    figures.worst_at = "patch " + std::to_string(p) + " corner " + std::to_string(c) + " " + what +
                       " t " + std::to_string(t) + " (vertex " + std::to_string(v) + ", " +
                       kindName(creases.vertex_kind[v]) + ")";
  };
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    if (!limit.hasLimitSurface(p)) {
      throw std::runtime_error("patch " + std::to_string(p) + " has no limit surface in Bfr");
    }
    const ref::LimitFace face = limit.face(p);
    const auto fv = control.facePositions(p);
    const int size = int(fv.size());
    for (int c = 0; c < size; ++c) {
      const uint32_t a = fv[size_t(c)], b = fv[size_t((c + 1) % size)];
      if (creases.vertex_kind[a] != SharpVertexKind::kDart) {
        const mesh::Vec2d uv = bfrEdgeUv(size, c, 0.0);
        compare(p, c, 0.0, face.evaluate(uv.x, uv.y).position, "position");
        ++figures.corners;
      }
      if (!creases.isSharp(a, b) || !crease_end(a) || !crease_end(b)) continue;
      ++figures.curve_sides;
      for (double t : {0.1, 0.25, 0.4, 0.5, 0.66, 0.9}) {
        const mesh::Vec2d uv = bfrEdgeUv(size, c, t);
        compare(p, c, t, face.evaluate(uv.x, uv.y).position, "crease curve");
      }
    }
  }
  return figures;
}

// A message with its numbers and file names taken out: what kind of failure or refusal.
std::string kindOf(const std::string& message) {
  std::string kind;
  size_t start = 0;
  while (start <= message.size()) {
    size_t end = message.find(' ', start);
    if (end == std::string::npos) end = message.size();
    const std::string word = message.substr(start, end - start);
    const bool file = word.find(".obj") != std::string::npos;
    for (char ch : file ? std::string(word.back() == ':' ? "OBJ:" : "OBJ") : word) {
      const bool digit = std::isdigit(static_cast<unsigned char>(ch)) || ch == '.' || ch == '-';
      if (!digit) {
        kind += ch;
      } else if (kind.empty() || kind.back() != '#') {
        kind += '#';
      }
    }
    if (end < message.size()) kind += ' ';
    start = end + 1;
  }
  return kind;
}

// Messages counted by kind, with the first seed of each.
struct KindCounts {
  std::map<std::string, std::pair<size_t, uint64_t>> counts;
  void add(const std::string& message, uint64_t seed) {
    counts.try_emplace(kindOf(message), 0, seed).first->second.first++;
  }
  void print(const char* what) const {
    for (const auto& [kind, seen] : counts) {
      std::printf("[crease stress] %s %5zu x (first seed %llu) %s\n", what, seen.first,
                  (unsigned long long)seen.second, kind.c_str());
    }
  }
};

struct TechniqueTally {
  size_t built = 0, refused = 0, ungraded = 0, corners = 0, curve_sides = 0;
  double worst = 0;
  std::string worst_shape;
  KindCounts refusals;
};

// Builds `shape` with `technique` (and `variant`); returns what went wrong, or "".
std::string runTechnique(const Technique& technique, const VariantInfo& variant,
                         const testing::StressShape& shape, TechniqueTally& tally) {
  const std::string who = technique.info().id + "/" + variant.name + ": ";
  try {
    const std::string reason = technique.checkSupport(shape.mesh);
    if (reason.find('\n') != std::string::npos)
      return who + "checkSupport: reason of several lines";
  } catch (const std::exception& error) {
    return who + "checkSupport threw: " + error.what();
  }
  BuiltSurface surface;
  try {
    surface = buildSurface(technique, shape.mesh, variant);
  } catch (const UnsupportedInput& refused) {
    const std::string reason = refused.what();
    if (reason.empty() || reason.find('\n') != std::string::npos) {
      return who + "refused without a one-line reason: '" + reason + "'";
    }
    ++tally.refused;
    tally.refusals.add(reason, shape.seed);
    return "";
  } catch (const std::exception& error) {
    return who + "threw " + error.what();
  }
  ++tally.built;
  try {
    const LimitFigures figures = limitError(*surface, technique.info().id);
    tally.ungraded += !figures.graded;
    tally.corners += figures.corners;
    tally.curve_sides += figures.curve_sides;
    if (figures.worst > tally.worst) {
      tally.worst = figures.worst;
      tally.worst_shape = shape.description + ": " + figures.worst_at;
    }
    if (figures.worst > kLimitTolerance) {
      char line[96];
      std::snprintf(line, sizeof line, "off the limit by %.3e of the diagonal at ", figures.worst);
      return who + line + figures.worst_at;
    }
  } catch (const std::exception& error) {
    return who + "oracle: " + error.what();
  }
  return "";
}

// Failures: the first kMaxReported in full (with the shape's OBJ in a scratch folder), and
// every one counted by kind.
struct FailureLog {
  static constexpr size_t kMaxReported = 20;
  size_t failed = 0;
  KindCounts kinds;
  std::filesystem::path dir;

  void add(const testing::StressShape& shape, const std::string& failure) {
    if (failure.empty()) return;
    kinds.add(failure, shape.seed);
    if (++failed > kMaxReported) return;
    if (dir.empty()) dir = tb::testing::scratchDirectory("crease_stress");
    const std::string file = tb::testing::writeTextFile(
        dir / ("stress_" + std::to_string(shape.seed) + ".obj"), shape.obj);
    ADD_FAILURE() << shape.description << "\n  " << failure << "\n  OBJ: " << file;
  }
};

VariantInfo variantOf(const Technique& technique, const std::string& name) {
  for (const VariantInfo& v : technique.variants()) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no variant " + name + " of " + technique.info().id);
}

TEST(CreaseStress, GeneratedShapesBuildOrAreRefusedInOneLineAndMatchTheLimit) {
  const Technique* acc = TechniqueRegistry::instance().find("acc");
  const Technique* gregory = TechniqueRegistry::instance().find("gregory_acc");
  ASSERT_NE(acc, nullptr);
  ASSERT_NE(gregory, nullptr);
  const VariantInfo acc_variant = variantOf(*acc, "default");
  // gregory_acc's variants differ in what the preparation does with non-quads (quads_only)
  // and in the tangents (exact_tangents); each shape gets one of them.
  const std::vector<VariantInfo> gregory_variants = {variantOf(*gregory, "edge_symmetric"),
                                                     variantOf(*gregory, "quads_only"),
                                                     variantOf(*gregory, "exact_tangents")};
  const std::vector<testing::StressBase> bases = testing::stressBases();
  const uint64_t count = envOr("TB_STRESS_SHAPES", kDefaultShapes);
  const uint64_t first = envOr("TB_STRESS_FIRST_SEED", 1);
  const bool verbose = envOr("TB_STRESS_VERBOSE", 0) != 0;  // each shape on stderr, first
  const char* obj_file = std::getenv("TB_STRESS_OBJ");      // this file instead, `count` times
  const auto start = std::chrono::steady_clock::now();
  TechniqueTally acc_tally, gregory_tally;
  FailureLog log;
  for (uint64_t seed = first; seed < first + count; ++seed) {
    const testing::StressShape shape = obj_file != nullptr
                                           ? testing::loadStressShape(obj_file, seed)
                                           : testing::generateStressShape(bases, seed);
    if (verbose) std::fprintf(stderr, "%s\n", shape.description.c_str());
    const VariantInfo& gregory_variant = gregory_variants[seed % gregory_variants.size()];
    log.add(shape, runTechnique(*acc, acc_variant, shape, acc_tally));
    log.add(shape, runTechnique(*gregory, gregory_variant, shape, gregory_tally));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& [name, tally] :
       {std::pair{"acc", &acc_tally}, {"gregory_acc", &gregory_tally}}) {
    std::printf(
        "[crease stress] %-11s %llu shapes: %zu built (%zu not graded: interior valence "
        "2), %zu refused; against Bfr: %zu patch corners, %zu crease-curve sides, worst "
        "%.2e of the diagonal (%s)\n",
        name, (unsigned long long)count, tally->built, tally->ungraded, tally->refused,
        tally->corners, tally->curve_sides, tally->worst, tally->worst_shape.c_str());
    if (verbose) tally->refusals.print(name);
  }
  std::printf("[crease stress] seeds %llu..%llu, %zu failures, %.1f s\n", (unsigned long long)first,
              (unsigned long long)(first + count - 1), log.failed, seconds);
  log.kinds.print("failure");
  EXPECT_EQ(log.failed, 0u);
  if (obj_file != nullptr) return;
  // The shapes exercise both outcomes (most build; cone points, and non-quads for acc, are
  // refused), and the oracle sees corners and crease curves.
  EXPECT_GT(gregory_tally.built, count / 2);
  EXPECT_GT(gregory_tally.refused, 0u);
  EXPECT_GT(acc_tally.built, count / 3);
  EXPECT_GT(gregory_tally.curve_sides + acc_tally.curve_sides, count);
}

// Regression tests: one small shape per configuration the stress test found broken.

// gregory_acc's variants that patch triangles natively (quads_only refines them away).
const char* const kTriangleVariants[] = {"edge_symmetric", "exact_tangents"};

// Builds `obj` with technique `id`/`variant`, which must succeed, and grades it (limitError).
LimitFigures buildAndGrade(const std::string& id, const std::string& variant,
                           const mesh::Mesh& mesh, BuiltSurface* out = nullptr) {
  const Technique& technique = *TechniqueRegistry::instance().find(id);
  BuiltSurface surface = buildSurface(technique, mesh, variantOf(technique, variant));
  const LimitFigures figures = limitError(*surface, id);
  EXPECT_TRUE(figures.graded);
  EXPECT_LE(figures.worst, kLimitTolerance) << id << "/" << variant << ": " << figures.worst_at;
  if (out != nullptr) *out = std::move(surface);
  return figures;
}

// The crease B-spline's limit point at crease vertex v between b0 and b1.
mesh::Vec3d creaseLimit(const mesh::Mesh& mesh, uint32_t v, uint32_t b0, uint32_t b1) {
  return (mesh.positions[v] * 4.0 + mesh.positions[b0] + mesh.positions[b1]) * (1.0 / 6);
}

// Interior crease vertex 0 (two sharp edges) of six triangles: sectors of 2 and 4 faces.
// Before: its frames came from the smooth refined ring, rotated per sector, so the two
// sectors formed different edge points along each sharp edge (std::logic_error "the sectors
// of vertex 0 disagree on the edge point toward 1"). Now each sector is framed on its
// refined copy with the crease rules: P is the crease curve's limit point.
TEST(CreaseStressRegression, TriangleCreaseVertexSplitUnevenly) {
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0.3\nv 1 0 0\nv 0.5 0.866 0.1\nv -0.5 0.866 -0.1\nv -1 0 0.2\n"
      "v -0.5 -0.866 0\nv 0.5 -0.866 0.15\n"
      "f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 6\nf 1 6 7\nf 1 7 2\n"
      "t crease 2/1/0 0 1 10\nt crease 2/1/0 0 3 10\n",
      "fan6.obj");
  for (const char* variant : kTriangleVariants) {
    BuiltSurface surface;
    const LimitFigures figures = buildAndGrade("gregory_acc", variant, mesh, &surface);
    EXPECT_EQ(figures.curve_sides, 10u);  // 2 spokes from both sides, 6 rim edges
    // Face 0 = (0, 1, 2): corner 0 is vertex 0.
    EXPECT_LE(length(surface->evaluate(0, {1, 0, 0}).position - creaseLimit(mesh, 0, 1, 3)), 1e-15);
  }
}

// The same at valence 4, the sharp edges opposite: the rotations were exact quarter turns,
// so the sectors agreed, on the smooth limit point (1.9e-2 of the diagonal off the crease
// curve, found by the stress test as a Bfr mismatch, not an exception).
TEST(CreaseStressRegression, TriangleCreaseVertexSplitInHalves) {
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0.3\nv 1 0 0\nv 0 1 0.1\nv -1 0 0.2\nv 0 -1 0\n"
      "f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\n"
      "t crease 2/1/0 0 1 10\nt crease 2/1/0 0 3 10\n",
      "fan4.obj");
  for (const char* variant : kTriangleVariants) {
    BuiltSurface surface;
    buildAndGrade("gregory_acc", variant, mesh, &surface);
    EXPECT_LE(length(surface->evaluate(0, {1, 0, 0}).position - creaseLimit(mesh, 0, 1, 3)), 1e-15);
  }
}

// Edge-only boundary: a boundary vertex of one triangle is a crease vertex of the boundary
// curve. Before: its frame came from refineOnce, which makes such a vertex a corner (the
// edge-and-corner rule), so P sat 6.1e-2 of the diagonal off the limit.
TEST(CreaseStressRegression, OneTriangleBoundaryVertexUnderEdgeOnly) {
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0.2\nv 2 0 0\nv 0.5 1 0.3\nv 1.5 1 -0.1\nv 1 2 0.4\n"
      "f 1 2 4\nf 2 5 4\nf 2 3 5\nf 4 5 6\n"
      "t interpolateboundary 1/0/0 2\n",
      "strip.obj");
  for (const char* variant : kTriangleVariants) {
    BuiltSurface surface;
    buildAndGrade("gregory_acc", variant, mesh, &surface);
    // Face 3 = (3, 4, 5): vertex 5 has that face alone, between boundary neighbours 3 and 4.
    EXPECT_LE(length(surface->evaluate(3, {0, 0, 1}).position - creaseLimit(mesh, 5, 3, 4)), 1e-15);
  }
}

// Boundary interpolation none with the boundary edges at a grid corner tagged sharp: face 0
// keeps a limit surface (Far's holes, Bfr), and the other faces at the boundary are holes.
// Before: the control mesh, rebuilt because holes moved last, dropped the boundary edges'
// tags, so Bfr over it (the error measure's reference) denied face 0 a limit surface though
// acc and gregory_acc patch it.
TEST(CreaseStressRegression, BoundaryNoneKeepsExplicitlySharpBoundaryEdges) {
  std::string obj;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      obj += "v " + std::to_string(i) + " " + std::to_string(j) + " " +
             std::to_string(0.1 * ((i * 7 + j * 3) % 4)) + "\n";
    }
  }
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const int a = 1 + i + 4 * j;
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 5) +
             " " + std::to_string(a + 4) + "\n";
    }
  }
  obj +=
      "t crease 2/1/0 0 1 10\nt crease 2/1/0 1 2 10\nt crease 2/1/0 0 4 10\n"
      "t crease 2/1/0 4 8 10\nt interpolateboundary 1/0/0 0\n";
  const mesh::Mesh mesh = mesh::loadObjText(obj, "grid_none.obj");
  const ref::LimitSurface input_limit(mesh, osd::Scheme::kCatmullClark);
  ASSERT_TRUE(input_limit.hasLimitSurface(0));
  for (const auto& [id, variant] :
       {std::pair{"acc", "default"}, {"gregory_acc", "edge_symmetric"}}) {
    BuiltSurface surface;
    const LimitFigures figures = buildAndGrade(id, variant, mesh, &surface);
    ASSERT_EQ(surface->patchCount(), 2u) << id;  // faces 0 and 4
    EXPECT_EQ(surface->sourceFace(0), 0u) << id;
    EXPECT_EQ(surface->sourceFace(1), 4u) << id;
    EXPECT_EQ(figures.corners, 8u) << id;
    const ref::LimitSurface limit(surface->controlMesh(), osd::Scheme::kCatmullClark);
    for (size_t f = 0; f < surface->controlMesh().faceCount(); ++f) {
      EXPECT_EQ(limit.hasLimitSurface(f), f < surface->patchCount()) << id << " face " << f;
    }
  }
}

}  // namespace
}  // namespace tb::techniques
