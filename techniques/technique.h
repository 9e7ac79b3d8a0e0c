// The plug-in interface every technique implements, and the plain structs it
// returns. A technique lives in techniques/<id>/, registers itself with
// TB_REGISTER_TECHNIQUE, and is then found by the CLI and every measure; adding
// one touches no harness code.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/gpu/patch_program_desc.h"
#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"
#include "core/tess/tessellator.h"
#include "techniques/batch_eval.h"
#include "techniques/counting_scalar.h"
#include "techniques/simulation.h"

namespace tb::techniques {

enum class TechniqueFamily {
  kSurface,     // turns a control mesh into patches evaluated by the tessellator
  kSimulation,  // steps a simulation (wave particles, soft bodies)
};

// The subdivision surface a technique approximates; the error measure grades it
// against that scheme's exact limit (OpenSubdiv Bfr) of controlMesh().
enum class LimitScheme { kLoop, kCatmullClark };

struct TechniqueInfo {
  std::string id;  // "phong"; lower case, used on the command line and in results
  TechniqueFamily family;
  std::string title;     // "Phong tessellation"
  std::string citation;  // "Boubekeur & Alexa, SIGGRAPH Asia 2008"
  std::string input;     // what input it accepts, in words
};

struct VariantInfo {
  std::string name;                          // "alpha0.75"; unique within the technique
  std::string description;                   // one line for reports
  std::map<std::string, double> parameters;  // numeric parameters, e.g. {"alpha": 0.75}
  // The default variant's surface evaluated in another float operation order: its double
  // evaluate() is the default's to rounding, so its surface-error figures repeat the
  // default's (the default suite grades them once; VariantPolicy::kEveryDistinctSurface).
  bool evaluation_order_only = false;
  // Run by --suite full only: a costlier variant the default suite's time budget leaves out.
  bool full_suite_only = false;
  // Non-empty: a control, a variant made to show a failure (what it shows, one line). It is
  // measured like any other and never recommended: `advise` and the report's choice section
  // exclude it (results.json: context.selection.techniques[].controls).
  std::string control = {};
};

// Bytes a technique keeps resident to draw one asset, before tessellation.
struct DataFootprint {
  uint64_t control_mesh_bytes = 0;  // vertex attributes + index buffer of the control mesh
  uint64_t patch_data_bytes = 0;    // per-patch control points, coefficients, flags
  uint64_t stencil_bytes = 0;       // stencil tables and topology-combination classes
  // Distinct stencil classes: patches whose control points share one weight table (seed
  // 000: the tuple of corner valences and boundary flags, up to rotation; its example
  // reduces 105 patches to 23). 0 when the technique has no such classes. Best case 1.
  uint64_t topology_combinations = 0;
  // A displaced surface's map as the GPU keeps it (gpuResidentBytes); 0 when undisplaced.
  uint64_t displacement_map_bytes = 0;
  uint64_t total() const {
    return control_mesh_bytes + patch_data_bytes + stencil_bytes + displacement_map_bytes;
  }
  bool operator==(const DataFootprint&) const = default;
};

struct SurfacePoint {
  mesh::Vec3d position;
  mesh::Vec3d normal;  // unit length, or zero where the surface is degenerate
};

// The same in float: what the technique's shaders compute.
struct SurfacePointF {
  mesh::Vec3f position;
  mesh::Vec3f normal;  // as the TES outputs it (normalised there when the shader normalises)
};

// What a conservative patch culler may assume about one patch (the culling measure,
// harness/lod/cull_policy.h), in world units of controlMesh(). Computed once per
// patch in double; the harness rounds it outward for the device.
struct PatchCullBounds {
  // Points whose convex hull contains the whole patch: its Bezier, Gregory or PN control
  // net (a patch lies in the convex hull of its control points). Never empty.
  std::vector<mesh::Vec3d> hull;
  // Vectors whose non-negative combinations include the geometric normal dp/du x dp/dv of
  // the position patch at every point of the domain (never a shading normal), oriented to
  // the front: the side the control face's winding (counter-clockwise, OBJ order) faces,
  // which is the side the technique's tessellated triangles face. For a polynomial patch,
  // the control points of its normal patch (Sederberg & Meyers 1988; the cone of normals
  // of Shirman & Abi-Ezzi 1993 is built from them). Empty: no bound, so no cone culling.
  std::vector<mesh::Vec3d> normal_generators;
  // The position patch as a polynomial in Bernstein form, for the tangent_plane policy
  // (harness/lod/tangent_plane.h); empty when the patch is not polynomial (a Gregory patch
  // whose face points differ, Phong's edge variant) or the technique gives none. On a quad
  // patch (bezier_degree + 1)^2 points c[i + (bezier_degree + 1) j], i along u; on a
  // triangle patch triangleNetSize(bezier_degree) points in techniques/common/
  // bernstein_poly.h's order. Its p_u x p_v (quad) or D_1 x D_2 (triangle, patch_bounds.h)
  // faces the front, or the back when bezier_mirrored.
  std::vector<mesh::Vec3d> bezier_net;
  int bezier_degree = 0;
  bool bezier_mirrored = false;
};

// Bounds on the second derivatives of one patch (SurfacePatches::curvatureBounds), what the
// error_bound factor policy (harness/lod/factor_policy.h) turns into tessellation levels:
// a piecewise-linear interpolant of a C^2 curve on segments of parameter length h is within
// h^2 / 8 sup|C''| of it (Wang's formula for a Bezier curve of degree d: sup|C''| <=
// d (d - 1) max|P_{i+2} - 2 P_{i+1} + P_i|), and on an n x n grid of a patch within
// (uu + 2 uv + vv) / (8 n^2) (Filip, Magedson & Markot, CAGD 1986). World units of
// controlMesh() per unit parameter squared; computed in double from the patch's exact form,
// never sampled (a sampled maximum is no bound).
struct CurvatureBounds {
  // sup over the domain of |d2S/du2|, |d2S/dudv| and |d2S/dv2|, (u, v) the DomainCoord of
  // evaluate(); on a triangle patch the first two barycentric coordinates with w = 1 - u - v
  // dependent. Best 0 (an affine patch); larger means more bending.
  double uu = 0, uv = 0, vv = 0;
  // Per outer edge j in gl_TessLevelOuter order (quad: u = 0, v = 0, u = 1, v = 1; triangle:
  // u = 0, v = 0, w = 0; a triangle's edge[3] is 0): sup |C''| of the edge's boundary curve C
  // parameterised from 0 to 1 between its two corners, from what determines that curve alone
  // (a Bezier net's boundary row), so the two patches of a shared edge agree up to rounding.
  std::array<double, 4> edge{};
  // Per outer edge: points whose convex hull contains the edge curve (the boundary row of a
  // Bezier net; the patch's hull where no tighter set is known). Never empty for j < edges.
  std::array<std::vector<mesh::Vec3d>, 4> edge_hull;
  // Points whose convex hull contains the whole patch (as PatchCullBounds::hull).
  std::vector<mesh::Vec3d> hull;
};

// Exact scalar operation counts of one patch (docs/MEASURES.md), from the technique's
// evaluators run with CountingScalar in the shader's operation order.
struct OperationProfile {
  OperationCounts per_patch_setup;  // control points etc., once per patch (TCS work)
  OperationCounts per_vertex;       // one evaluated vertex: position + normal (TES work)
  std::string note;                 // what was counted, e.g. "symmetric_fma order, tangent patches"
};

// The patches a surface technique built for one asset and variant: the surface
// capability of a TechniqueInstance.
class SurfacePatches {
 public:
  virtual ~SurfacePatches() = default;
  // The domain of patch p; patches may mix domains (gregory_acc: quads and triangles).
  virtual PatchDomain patchDomain(size_t patch) const = 0;
  // Default: quad patches approximate Catmull-Clark, triangle patches Loop.
  virtual LimitScheme approximates() const {
    return patchCount() > 0 && patchDomain(0) == PatchDomain::kQuad ? LimitScheme::kCatmullClark
                                                                    : LimitScheme::kLoop;
  }
  virtual size_t patchCount() const = 0;
  // The mesh the patches are built over: patch p covers face p of it (for
  // `phong`, the fan-triangulated input). Measures read its render vertices.
  virtual const mesh::Mesh& controlMesh() const = 0;
  // Control-mesh positions at the patch corners, in domain order (3 for a triangle
  // patch, the 4th then unused); shared edges between patches are found through these.
  virtual std::array<uint32_t, 4> patchCorners(size_t patch) const = 0;
  // The face of the input asset the patch came from (for parametric error).
  virtual uint32_t sourceFace(size_t patch) const = 0;
  virtual SurfacePoint evaluate(size_t patch, const DomainCoord& coord) const = 0;
  // evaluate(patch, coord).position, bit for bit; a technique whose normal costs overrides
  // it (BatchOutput::kPositions evaluates point by point with it).
  virtual mesh::Vec3d evaluatePosition(size_t patch, const DomainCoord& coord) const {
    return evaluate(patch, coord).position;
  }
  // The surface in float with the operation order of the technique's TES (and TCS set-up),
  // at gl_TessCoord exactly as the tessellator emits it. The CPU side of every GPU
  // comparison and of the crack measure: two patches that share an edge are watertight
  // in float only if this gives bitwise-equal points there.
  virtual SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& coord) const = 0;
  // The GPU programs that evaluate these patches (shaders/<id>/, run by
  // core/gpu/patch_program.h): one per patch domain for a technique with several (each
  // with GpuPatchProgram::patch_ids), else one whose patch p is this object's patch p.
  // Together they cover every patch once. Empty when there is no GPU path.
  virtual std::vector<gpu::GpuPatchProgram> gpuPrograms() const { return {}; }
  // Operation counts for patch p at an interior domain point, or nullopt when the
  // technique does not count. Counts may differ between regular and irregular patches.
  virtual std::optional<OperationProfile> operationProfile(size_t patch) const {
    (void)patch;
    return std::nullopt;
  }
  // Conservative bounds of patch p for culling (PatchCullBounds), or nullopt when the
  // technique gives none: then only the culling policies that read corners alone
  // (backface_lp2, frustum_lp2 with a global margin) can cull its patches.
  virtual std::optional<PatchCullBounds> cullBounds(size_t patch) const {
    (void)patch;
    return std::nullopt;
  }
  // Second-derivative bounds of patch p (CurvatureBounds), or nullopt when the technique
  // gives none (the error_bound policy then skips it with that reason). The default reads
  // cullBounds()'s Bezier net (techniques/common/curvature_bounds.h) when it has one.
  virtual std::optional<CurvatureBounds> curvatureBounds(size_t patch) const;
  virtual DataFootprint footprint() const = 0;
  // Non-fatal notes gathered while building ("3 quads fan-triangulated").
  virtual const std::vector<std::string>& warnings() const = 0;

  // Batched evaluation (techniques/batch_eval.h): the points `coords` of one tessellation
  // pattern on patches of `domain`, prepared once (a technique with a batched kernel
  // computes their basis weights here). The default keeps only the points.
  virtual std::unique_ptr<BatchPattern> makeBatchPattern(PatchDomain domain,
                                                         std::vector<DomainCoord> coords,
                                                         BatchOutput output) const {
    return std::make_unique<BatchPattern>(domain, std::move(coords), output);
  }
  // Every point of `pattern` on patch `patch` into `out` (reset to the pattern's size).
  // Equal to evaluate() point by point up to rounding (~1e-12 relative). The default is
  // evaluateBatchPointByPoint; a technique overrides it with its kernel and falls back to
  // the default for a pattern it did not make. Throws std::invalid_argument when the
  // pattern's domain is not the patch's.
  virtual void evaluateBatch(size_t patch, const BatchPattern& pattern, BatchPoints& out) const {
    evaluateBatchPointByPoint(patch, pattern, out);
  }
  // evaluate() at every point: position and normal, no derivatives.
  void evaluateBatchPointByPoint(size_t patch, const BatchPattern& pattern, BatchPoints& out) const;
};

inline void SurfacePatches::evaluateBatchPointByPoint(size_t patch, const BatchPattern& pattern,
                                                      BatchPoints& out) const {
  if (pattern.domain() != patchDomain(patch)) {
    throw std::invalid_argument("evaluateBatch: patch " + std::to_string(patch) +
                                " and the batch pattern have different domains");
  }
  out.reset(pattern.pointCount());
  if (pattern.output() == BatchOutput::kPositions) {
    for (size_t i = 0; i < pattern.pointCount(); ++i) {
      BatchPoints::set(out.position, i, evaluatePosition(patch, pattern.coords()[i]));
    }
    return;
  }
  for (size_t i = 0; i < pattern.pointCount(); ++i) {
    const SurfacePoint point = evaluate(patch, pattern.coords()[i]);
    BatchPoints::set(out.position, i, point.position);
    BatchPoints::set(out.normal, i, point.normal);
  }
  out.has_normals = true;
}

// Thrown by Technique::build when the asset breaks a rule the technique needs.
// The message names the technique, the element and the rule, e.g.
// "acc: face 17 has 3 vertices; ACC needs quads".
class UnsupportedInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a technique instance can do. Each capability is null when absent; a measure
// declares which it needs (harness/measures/measure.h) and the suite never hands it an
// instance without them. One instance may have both (a simulated skin that renders as
// patches).
class TechniqueInstance {
 public:
  virtual ~TechniqueInstance() = default;
  virtual const SurfacePatches* surface() const { return nullptr; }
  virtual Simulation* simulation() { return nullptr; }
  const Simulation* simulation() const {
    return const_cast<TechniqueInstance*>(this)->simulation();
  }
};

// The instance of a surface technique: owns its patches and nothing else.
class SurfaceInstance final : public TechniqueInstance {
 public:
  explicit SurfaceInstance(std::unique_ptr<SurfacePatches> patches)
      : patches_(std::move(patches)) {}
  const SurfacePatches* surface() const override { return patches_.get(); }

 private:
  std::unique_ptr<SurfacePatches> patches_;
};

// The instance of a simulation technique: owns its simulation and nothing else.
class SimulationInstance final : public TechniqueInstance {
 public:
  explicit SimulationInstance(std::unique_ptr<Simulation> simulation)
      : simulation_(std::move(simulation)) {}
  Simulation* simulation() override { return simulation_.get(); }

 private:
  std::unique_ptr<Simulation> simulation_;
};

// What a technique builds from: the asset's mesh (surface techniques) and/or a scenario
// (simulations). Absent parts are null; build throws UnsupportedInput when it needs one.
struct TechniqueInput {
  const mesh::Mesh* mesh = nullptr;
  const Scenario* scenario = nullptr;
};

class Technique {
 public:
  virtual ~Technique() = default;
  virtual const TechniqueInfo& info() const = 0;
  // The first variant is the default.
  virtual std::vector<VariantInfo> variants() const = 0;
  // Empty string when the mesh is supported; otherwise the reason (one line).
  virtual std::string checkSupport(const mesh::Mesh& mesh) const = 0;
  // Builds the instance for one input and variant; throws UnsupportedInput when the
  // input breaks a rule of the technique (or lacks the mesh or scenario it needs).
  virtual std::unique_ptr<TechniqueInstance> build(const TechniqueInput& input,
                                                   const VariantInfo& variant) const = 0;
  // The optional capabilities the simulations it builds have (techniques/simulation.h);
  // none by default, and none for a surface technique.
  virtual SimulationCapabilities simulationCapabilities() const { return {}; }
};

// The mesh of `input`, or UnsupportedInput naming the technique when there is none.
const mesh::Mesh& requireMesh(const TechniqueInfo& technique, const TechniqueInput& input);

// A built instance whose surface is used directly: `*built` and `built->` are the
// SurfacePatches, and the instance stays alive with it. For callers that need only the
// surface (tests, benches, tools); the suite reads capabilities itself.
class BuiltSurface {
 public:
  BuiltSurface() = default;  // empty, like a null pointer
  BuiltSurface(std::nullptr_t) {}
  explicit BuiltSurface(std::unique_ptr<TechniqueInstance> instance);
  explicit operator bool() const { return surface_ != nullptr; }
  bool operator==(std::nullptr_t) const { return surface_ == nullptr; }
  const SurfacePatches& operator*() const { return *surface_; }
  const SurfacePatches* operator->() const { return surface_; }
  const SurfacePatches* get() const { return surface_; }
  TechniqueInstance& instance() { return *instance_; }

 private:
  std::unique_ptr<TechniqueInstance> instance_;
  const SurfacePatches* surface_ = nullptr;
};

// technique.build({&mesh}, variant) for a technique with a surface; throws
// UnsupportedInput as build does, and std::logic_error when the instance has no surface.
BuiltSurface buildSurface(const Technique& technique, const mesh::Mesh& mesh,
                          const VariantInfo& variant);

const char* toString(TechniqueFamily family);
const char* toString(PatchDomain domain);

}  // namespace tb::techniques
