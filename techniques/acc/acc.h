// The `acc` technique: Loop & Schaefer's approximation of Catmull-Clark surfaces by
// bicubic Bézier geometry patches plus tangent patches (techniques/acc/acc_patch.h).
#pragma once

#include "techniques/common/bezier_eval.h"
#include "techniques/technique.h"

namespace tb::acc {

// Largest vertex valence accepted; the GPU reads rings of any valence up to this
// from storage buffers (the stencil table holds one tangent mask per valence).
inline constexpr uint32_t kMaxValence = 32;

class AccTechnique final : public Technique {
 public:
  const TechniqueInfo& info() const override;
  // "default" (tangent patches, symmetric FMA order), "no_tangent" (normal from the
  // geometry patch's derivatives), and the other evaluation orders with tangent
  // patches: "asymmetric", "symmetric_nofma", "symmetric_edges".
  std::vector<VariantInfo> variants() const override;
  std::string checkSupport(const Mesh& mesh) const override;
  std::unique_ptr<TechniqueInstance> build(const TechniqueInput& input,
                                           const VariantInfo& variant) const override;
};

// Parameters of a variant: "order" (BezierOrder as a number) and "tangent" (0/1).
BezierOrder variantOrder(const VariantInfo& variant);
bool variantTangentPatches(const VariantInfo& variant);

}  // namespace tb::acc

namespace tb::acc {
// Distinct corner (valence, boundary) tuples up to rotation among the patches: the
// stencil table holds one entry per combination. 0 for patches not built by acc.
size_t topologyCombinationCount(const SurfacePatches& patches);
}  // namespace tb::acc
