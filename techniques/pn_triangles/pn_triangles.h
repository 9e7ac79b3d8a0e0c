// The `pn_triangles` technique: curved PN triangles (Vlachos et al. 2001) with the crack
// fixes of seed 003 (geometry normals with edge flags, boundary flags, rounding) and
// PN-AEN (McDonald & Kilgard, NVIDIA 2010).
#pragma once

#include "techniques/technique.h"

namespace tb::pn_triangles {

class PnTrianglesTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
};

}  // namespace tb::pn_triangles
