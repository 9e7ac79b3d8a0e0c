// The `osd_adaptive` technique: OpenSubdiv Far's feature-adaptive patch table (Nießner,
// Loop, Meyer & DeRose, "Feature-Adaptive GPU Rendering of Catmull-Clark Subdivision
// Surfaces", ACM TOG 31(1) 2012; OpenSubdiv). The baseline row: regular B-spline patches
// around regular faces, adaptive refinement towards extraordinary vertices and creases down
// to the isolation level, and end caps (Gregory basis or B-spline basis) there.
// evaluate() is Far's own (PatchMap, EvaluateBasis<double>): the oracle. On the GPU
// (gpuPrograms(), shaders/osd_adaptive/) one patch per base face: the TES finds the face's
// Far patch covering gl_TessCoord and evaluates it with osd_basis.h's basis; evaluateFloat
// is its CPU twin.
#pragma once

#include <optional>

#include "techniques/technique.h"

namespace tb::osd_adaptive {

enum class EndCap { kGregoryBasis = 0, kBSplineBasis = 1 };

class OsdAdaptiveTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  // "iso2_gregory" only (the default suite's budget); parameters "isolation" and "endcap"
  // give any other level and B-spline basis end caps.
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
};

// Parameters of a variant: "isolation" (Far adaptive isolation level, 0..10) and
// "endcap" (EndCap as a number).
int variantIsolation(const techniques::VariantInfo& variant);
EndCap variantEndCap(const techniques::VariantInfo& variant);

// What the patch table of one built instance holds (for tests and the report): 0 for
// patches not built by osd_adaptive.
struct PatchTableCounts {
  size_t base_faces = 0;
  size_t patches = 0;           // Far patches in the table
  size_t regular_patches = 0;   // 16-point B-spline patches (boundary masks included)
  size_t end_caps = 0;          // Gregory basis or B-spline basis end caps
  size_t refined_vertices = 0;  // vertices of every refinement level, base level included
  size_t local_points = 0;      // end-cap points computed by the local point stencils
};
PatchTableCounts patchTableCounts(const techniques::SurfacePatches& patches);

// True when the Far patch that covers (u, v) of base face `face` is a regular B-spline patch
// (not an end cap). False for patches not built by osd_adaptive.
bool isRegularAt(const techniques::SurfacePatches& patches, size_t face, double u, double v);

// Base face `face` at (u, v) with osd_basis.h's weights in double (the GPU's sub-patch
// search and basis, evaluateFloat's in double) instead of Far's PatchMap and EvaluateBasis:
// for tests of the basis against evaluate(). Nullopt for patches not built by osd_adaptive.
std::optional<techniques::SurfacePoint> evaluateOwnBasis(const techniques::SurfacePatches& patches,
                                                         size_t face, double u, double v);

}  // namespace tb::osd_adaptive
