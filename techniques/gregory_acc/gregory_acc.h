// The `gregory_acc` technique: Catmull-Clark limit surfaces approximated by quad Gregory
// patches (Loop, Schaefer, Ni, Castaño, SIGGRAPH Asia 2009; seed 000 "Gregory ACC"), and
// triangle Gregory patches for triangle faces (the `quads_only` variant refines non-quad
// faces once instead). Manifold polygon meshes with creases, corners, holes and any
// boundary interpolation (see gregory_stencils.h, and checkGregorySupport for the exact
// rules and messages).
#pragma once

#include "techniques/technique.h"

namespace tb::gregory_acc {

class GregoryAccTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
};

// Parameter "crease_face_budget" of a variant: faces the refinement of semi-sharp creases
// may reach (kDefaultCreaseFaceBudget in techniques/common/crease_refinement.h when absent).
size_t variantCreaseFaceBudget(const techniques::VariantInfo& variant);

}  // namespace tb::gregory_acc
