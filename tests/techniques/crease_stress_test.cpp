// Stress test of the crease preparation (techniques/common/crease_refinement.h) and the two
// techniques built on it, acc and gregory_acc, over creased shapes generated from fixed
// seeds (crease_stress_support.h: bundled meshes, refined 0 to 2 times, with random
// infinitely sharp and semi-sharp creases, corner tags, holes, boundary rules). Every shape
// either builds or is refused with an UnsupportedInput of one line; anything else (a
// std::logic_error from a construction check, a crash) fails, naming the seed and the
// shape. Oracle for the shapes that build: the OpenSubdiv Bfr limit position at every patch
// corner (the limit of the mesh the patches honour, gregory_acc_test_support.h limitMeshOf),
// except at darts, where both techniques keep the smooth rules and are approximate.
//
// TB_STRESS_SHAPES=N runs N shapes (default kDefaultShapes), TB_STRESS_FIRST_SEED=S starts
// at seed S (default 1): `TB_STRESS_SHAPES=1 TB_STRESS_FIRST_SEED=1234 crease_stress_test`
// reproduces shape 1234 alone; a failing shape's OBJ is also written to a scratch folder.
// TB_STRESS_VERBOSE=1 prints each shape before it runs (a crash then names its shape);
// TB_STRESS_OBJ=file.obj runs that file instead (the variant of gregory_acc still by seed).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
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

// Shapes run by default: about 12 s in Release on the 2-core CI machine.
constexpr uint64_t kDefaultShapes = 600;
// |patch corner - Bfr limit| / bounding-box diagonal. Every non-dart corner point is the
// limit position by construction (smooth: the limit mask, on its refined copy next to
// non-quads; crease: the crease B-spline's limit point; corner: the vertex); Bfr at
// ApproxLevel 10 agrees to rounding.
constexpr double kCornerTolerance = 1e-9;

uint64_t envOr(const char* name, uint64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 10) : fallback;
}

struct CornerFigures {
  size_t corners = 0;      // patch corners compared (darts excluded)
  double worst = 0;        // max |patch corner - limit| / diagonal
  std::string worst_at;    // "patch 3 corner 1 (vertex 7, crease)"
};

const char* kindName(SharpVertexKind kind) {
  static const char* const kNames[] = {"smooth", "dart", "crease", "corner", "cone"};
  return kNames[int(kind)];
}

// The patch corners against Bfr over the mesh the patches honour: the control mesh with its
// true remaining tags, or, where leftover semi-sharpness was rounded, with the rounded ones.
// The vertex kinds come from the control mesh's own preparation (nothing left to refine).
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

CornerFigures cornerLimitError(const SurfacePatches& patches, const std::string& technique) {
  const mesh::Mesh& control = patches.controlMesh();
  if (hasInteriorValence2(control)) return {};
  const CreasePreparation creases = prepareCreases(control, technique, 0);
  const ref::LimitSurface limit(gregory_acc::testing::limitMeshOf(patches, creases),
                                osd::Scheme::kCatmullClark);
  const double diagonal = mesh::diagonalOf(mesh::boundsOf(control));
  CornerFigures figures;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    if (!limit.hasLimitSurface(p)) {
      throw std::runtime_error("patch " + std::to_string(p) + " has no limit surface in Bfr");
    }
    const ref::LimitFace face = limit.face(p);
    const auto fv = control.facePositions(p);
    const int size = int(fv.size());
    const PatchDomain domain = patches.patchDomain(p);
    for (int c = 0; c < size; ++c) {
      const SharpVertexKind kind = creases.vertex_kind[fv[c]];
      if (kind == SharpVertexKind::kDart) continue;
      const mesh::Vec2d uv =
          ref::subFaceToFaceUv(osd::Scheme::kCatmullClark, size, c, mesh::Vec2d{0, 0});
      const mesh::Vec2d quad_uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      const mesh::Vec2d at = size == 4 ? quad_uv[c] : uv;
      const mesh::Vec3d exact = face.evaluate(at.x, at.y).position;
      const mesh::Vec3d ours =
          patches.evaluate(p, gregory_acc::testing::edgeCoord(domain, c, 0.0)).position;
      const double error = length(ours - exact) / diagonal;
      ++figures.corners;
      if (error > figures.worst) {
        figures.worst = error;
        figures.worst_at = "patch " + std::to_string(p) + " corner " + std::to_string(c) +
                           " (vertex " + std::to_string(fv[c]) + ", " + kindName(kind) + ")";
      }
    }
  }
  return figures;
}

struct TechniqueTally {
  size_t built = 0, refused = 0, corners = 0;
  double worst = 0;
  std::string worst_shape;
};

// Builds `shape` with `technique` (and `variant`); returns what went wrong, or "".
std::string runTechnique(const Technique& technique, const VariantInfo& variant,
                         const testing::StressShape& shape, TechniqueTally& tally) {
  const std::string who = technique.info().id + "/" + variant.name + ": ";
  try {
    const std::string reason = technique.checkSupport(shape.mesh);
    if (reason.find('\n') != std::string::npos) return who + "checkSupport: reason of several lines";
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
    return "";
  } catch (const std::exception& error) {
    return who + "threw " + error.what();
  }
  ++tally.built;
  try {
    const CornerFigures figures = cornerLimitError(*surface, technique.info().id);
    tally.corners += figures.corners;
    if (figures.worst > tally.worst) {
      tally.worst = figures.worst;
      tally.worst_shape = shape.description + ": " + figures.worst_at;
    }
    if (figures.worst > kCornerTolerance) {
      char line[96];
      std::snprintf(line, sizeof line, "corner off the limit by %.3e of the diagonal at ",
                    figures.worst);
      return who + line + figures.worst_at;
    }
  } catch (const std::exception& error) {
    return who + "oracle: " + error.what();
  }
  return "";
}

// Failures: the first kMaxReported in full (with the shape's OBJ in a scratch folder), and
// every one counted by kind (its message with the numbers and file name taken out).
struct FailureLog {
  static constexpr size_t kMaxReported = 20;
  size_t failed = 0;
  std::map<std::string, std::pair<size_t, uint64_t>> kinds;  // kind -> (count, first seed)
  std::filesystem::path dir;

  void add(const testing::StressShape& shape, const std::string& failure) {
    if (failure.empty()) return;
    std::string kind;
    for (char ch : std::regex_replace(failure, std::regex("stress_[0-9]+\\.obj"), "OBJ")) {
      if (!std::isdigit(static_cast<unsigned char>(ch)) || kind.empty() || kind.back() != '#')
        kind += std::isdigit(static_cast<unsigned char>(ch)) ? '#' : ch;
    }
    kinds.try_emplace(kind, 0, shape.seed).first->second.first++;
    if (++failed > kMaxReported) return;
    if (dir.empty()) dir = tb::testing::scratchDirectory("crease_stress");
    const std::string file = tb::testing::writeTextFile(
        dir / ("stress_" + std::to_string(shape.seed) + ".obj"), shape.obj);
    ADD_FAILURE() << shape.description << "\n  " << failure << "\n  OBJ: " << file;
  }
  void printKinds() const {
    for (const auto& [kind, seen] : kinds) {
      std::printf("[crease stress] %5zu x (first seed %llu) %s\n", seen.first,
                  (unsigned long long)seen.second, kind.c_str());
    }
  }
};

VariantInfo variantOf(const Technique& technique, const std::string& name) {
  for (const VariantInfo& v : technique.variants()) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no variant " + name + " of " + technique.info().id);
}

TEST(CreaseStress, GeneratedShapesBuildOrAreRefusedInOneLineAndMatchTheLimitAtCorners) {
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
  const char* obj_file = std::getenv("TB_STRESS_OBJ");        // this file instead, `count` times
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
  for (const auto& [name, tally] : {std::pair{"acc", &acc_tally}, {"gregory_acc", &gregory_tally}}) {
    std::printf("[crease stress] %-11s %llu shapes: %zu built, %zu refused; %zu patch corners "
                "against Bfr, worst %.2e of the diagonal (%s)\n",
                name, (unsigned long long)count, tally->built, tally->refused, tally->corners,
                tally->worst, tally->worst_shape.c_str());
  }
  std::printf("[crease stress] seeds %llu..%llu, %zu failures, %.1f s\n", (unsigned long long)first,
              (unsigned long long)(first + count - 1), log.failed, seconds);
  log.printKinds();
  EXPECT_EQ(log.failed, 0u);
  // The shapes exercise both outcomes: most build, and the cone points among them are refused.
  EXPECT_GT(gregory_tally.built, count / 2);
  EXPECT_GT(gregory_tally.refused, 0u);
}

}  // namespace
}  // namespace tb::techniques
