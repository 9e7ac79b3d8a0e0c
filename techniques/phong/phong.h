// The `phong` technique: Phong tessellation of a triangle mesh with vertex normals.
#pragma once

#include "techniques/technique.h"

namespace tb::phong {

constexpr double kDefaultAlpha = 0.75;  // the paper's recommended shape factor

class PhongTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
};

}  // namespace tb::phong
