// Stencils of the 20 Gregory control points of every quad (Loop, Schaefer, Ni, Castaño,
// SIGGRAPH Asia 2009): each point a weighted sum of control-mesh vertices, computed by the
// CPU evaluators and the TCS in the same order (ascending vertex index). Sharing
// (docs/ARCHITECTURE.md §5 rule 1): a corner point P belongs to its vertex and an edge point
// E(v->w) to its directed edge, ONE stencil each, referenced by every patch that uses it;
// Fp/Fm are per patch corner. Crease sectors (Kovacs et al. 2009, crease_refinement.h) and
// the rules per vertex kind: docs/derivations/acc_gregory.md and creases.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/gregory_acc/gregory_refine.h"

namespace tb::gregory_acc {

// Highest vertex valence accepted. The construction itself has no
// limit and nothing is sized by it (stencils are variable-length entries of one table,
// read by the TCS from a storage buffer); it bounds stencil sizes, hence the cost per
// patch: a P or E stencil touches the 1-ring of its vertex (at most 1 + 2n vertices for
// valence n), an Fp/Fm stencil two 1-rings (at most 4 + 4n), each entry one
// multiply-add of a vec3 and 8 bytes (index + float weight) on the GPU. Largest valence
// tested: 256 on the CPU (tests/techniques/valence_test.cpp), 64 on the GPU
// (assets/full_suite/pole64.obj).
constexpr uint32_t kMaxValence = 256;
// Largest face accepted (vertices). Kept at the former limit: the OBJ loader stops at
// 255, and a face of 5+ vertices becomes a vertex of that valence after refineOnce.
constexpr uint32_t kMaxFaceSize = 32;

// Control point slots of one patch corner; patch point index = corner * 5 + slot.
// Ep points along the edge to the next corner (corner + 1), Em to the previous one;
// Fp is the face point next to Ep's edge, Fm next to Em's edge.
//
// A quad has 4 corners (20 points: the bicubic Gregory patch). A triangle has 3 (15
// points): P, Ep, Em give the cubic boundary curves, shared with the neighbours; its
// Fp/Fm slots hold the quartic patch's interior Gregory points (gregory_eval.h: the
// quartic triangle's interior point next to corner c blends Fp and Fm of c). Slots
// 15..19 of a triangle are kNoStencil.
enum Slot : uint32_t { kP = 0, kEp = 1, kEm = 2, kFp = 3, kFm = 4 };
constexpr uint32_t kPointsPerPatch = 20;
constexpr uint32_t kPointsPerTriangle = 15;
constexpr uint32_t kNoStencil = UINT32_MAX;

struct GregoryStencils {
  // Stencil s has entries [offsets[s], offsets[s + 1]), sorted by vertex index.
  std::vector<uint32_t> offsets{0};
  std::vector<uint32_t> indices;  // control-mesh position index per entry
  std::vector<double> weights;    // weight per entry (affine: each stencil sums to 1)
  // Stencil id of every control point of every patch (patch p = face p; faces after the
  // patches, holes, have none; a triangle uses the first kPointsPerTriangle).
  std::vector<std::array<uint32_t, kPointsPerPatch>> patch_points;
  size_t sharedStencilCount = 0;  // P and E stencils (shared between patches)

  size_t stencilCount() const { return offsets.size() - 1; }
};

// Empty when the mesh is supported; otherwise one line naming the first offending
// element and the rule ("gregory_acc: <file>: face 3 (line 12) has 3 vertices; ...").
// Checked with the default crease face budget.
std::string checkGregorySupport(const mesh::Mesh& mesh);

// Which tangent mask places the edge points (see vertexFrame in gregory_rings.cpp).
enum class TangentMask {
  kPaper,       // Loop et al. 2009 / OpenSubdiv Far's Gregory basis (averaged ACC face
                // points); parametric error no larger than kExactLimit's on every bundled
                // asset measured
  kExactLimit,  // the Catmull-Clark limit tangent plane (Halstead et al. 1993)
};

// Stencils over `mesh`'s own vertices; `mesh` must have quads and triangles only. Its
// tags as prepareCreases sees them without refining (a finite sharpness is rounded); patch
// p is face p of that preparation's control mesh (the mesh's faces, holes moved last).
// Throws tb::UnsupportedInput for an unsupported mesh.
GregoryStencils buildGregoryStencils(const mesh::Mesh& mesh,
                                     TangentMask mask = TangentMask::kPaper);

// What becomes of faces that are not quads.
enum class NonQuadFaces {
  kTrianglePatches,  // triangles get triangle Gregory patches; a mesh with any face of
                     // 5+ vertices is refined once (refineOnce) and patched with quads
  kRefineOnce,       // any non-quad face: refine the whole mesh once, quads only
};

struct GregoryBuild {
  // The input prepared for creases: refined by OpenSubdiv while semi-sharp sharpness
  // remains (within the face budget), and once more when it has faces the patches do not
  // take natively next to sharp features; holes last. The stencils read its positions.
  techniques::CreasePreparation creases;
  // The mesh the patches are built over (patch p = its face p for p < patch_count):
  // creases.control when all its faces are quads (or quads and triangles, with
  // kTrianglePatches); otherwise creases.control refined once (refineOnce), all quads.
  mesh::Mesh control;
  bool refined = false;               // by refineOnce
  size_t patch_count = 0;             // faces of `control` with a patch (the rest: holes)
  std::vector<uint32_t> source_face;  // input face of each patch
  GregoryStencils stencils;           // over creases.control's positions
};

// Throws tb::UnsupportedInput with checkGregorySupport's message. `crease_face_budget`:
// prepareCreases' max_faces.
GregoryBuild buildGregory(const mesh::Mesh& mesh, TangentMask mask = TangentMask::kPaper,
                          NonQuadFaces non_quads = NonQuadFaces::kTrianglePatches,
                          size_t crease_face_budget = techniques::kDefaultCreaseFaceBudget);

}  // namespace tb::gregory_acc
