// The `acc` technique: Loop & Schaefer's approximation of Catmull-Clark surfaces by
// bicubic Bézier geometry patches plus tangent patches (techniques/acc/acc_patch.h).
#pragma once

#include "techniques/common/bezier_eval.h"
#include "techniques/technique.h"

namespace tb::acc {

// Largest vertex valence accepted. Nothing in the construction is sized by valence:
// the CPU and the TCS both read a vertex's ring (n edge and n diagonal neighbours) from
// storage buffers and its tangent mask (2n floats, one per valence in the mesh) from the
// stencil table, so the bound only keeps one corner's cost per patch finite. Cost of a
// corner of valence n, per patch: the corner point sums 2n + 1 terms and each of its two
// limit tangents 2n terms (about 6n + 1 multiply-adds per corner, in every TCS invocation
// that owns it); per vertex the GPU holds 8n bytes of ring slots and, per distinct valence,
// 8n bytes of mask. Largest valence tested: 256 on the CPU (tests/techniques/valence_test.cpp)
// and 64 on the GPU (assets/full_suite/pole64.obj).
inline constexpr uint32_t kMaxValence = 256;

class AccTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  // "default" (tangent patches, symmetric FMA order), "no_tangent" (normal from the
  // geometry patch's derivatives), and the other evaluation orders with tangent
  // patches: "asymmetric", "symmetric_nofma", "symmetric_edges".
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
};

// Parameters of a variant: "order" (BezierOrder as a number), "tangent" (0/1) and
// "crease_face_budget" (faces the refinement of semi-sharp creases may reach;
// kDefaultCreaseFaceBudget in techniques/common/crease_refinement.h when absent).
techniques::BezierOrder variantOrder(const techniques::VariantInfo& variant);
bool variantTangentPatches(const techniques::VariantInfo& variant);
size_t variantCreaseFaceBudget(const techniques::VariantInfo& variant);

}  // namespace tb::acc

namespace tb::acc {
// Distinct corner (valence, boundary) tuples up to rotation among the patches: the
// stencil table holds one entry per combination. 0 for patches not built by acc.
size_t topologyCombinationCount(const techniques::SurfacePatches& patches);
}  // namespace tb::acc
