// The `phong` technique: Phong tessellation of a triangle mesh with vertex normals.
#pragma once

#include "techniques/technique.h"

namespace tb::phong {

constexpr double kDefaultAlpha = 0.75;  // the paper's recommended shape factor

class PhongTechnique final : public Technique {
 public:
  const TechniqueInfo& info() const override;
  std::vector<VariantInfo> variants() const override;
  std::string checkSupport(const Mesh& mesh) const override;
  std::unique_ptr<TechniqueInstance> build(const TechniqueInput& input,
                                           const VariantInfo& variant) const override;
};

}  // namespace tb::phong
