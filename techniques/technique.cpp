// The non-virtual helpers of technique.h and variant_param.h.
#include "techniques/technique.h"

#include "techniques/common/curvature_bounds.h"
#include "techniques/variant_param.h"

namespace tb::techniques {

std::optional<CurvatureBounds> SurfacePatches::curvatureBounds(size_t patch) const {
  const std::optional<PatchCullBounds> bounds = cullBounds(patch);
  if (!bounds) return std::nullopt;
  return curvatureBoundsFromNet(*bounds, patchDomain(patch));
}

const mesh::Mesh& requireMesh(const TechniqueInfo& technique, const TechniqueInput& input) {
  if (input.mesh == nullptr) throw UnsupportedInput(technique.id + ": needs a mesh asset as input");
  return *input.mesh;
}

BuiltSurface::BuiltSurface(std::unique_ptr<TechniqueInstance> instance)
    : instance_(std::move(instance)), surface_(instance_ ? instance_->surface() : nullptr) {
  if (surface_ == nullptr) throw std::logic_error("buildSurface: the instance has no surface");
}

BuiltSurface buildSurface(const Technique& technique, const mesh::Mesh& mesh,
                          const VariantInfo& variant) {
  TechniqueInput input;
  input.mesh = &mesh;
  return BuiltSurface(technique.build(input, variant));
}

namespace detail {
void throwVariantParameterError(const TechniqueInfo& technique, const VariantInfo& variant,
                                std::string_view name, const std::string& problem) {
  throw VariantParameterError(technique.id + "/" + variant.name + ": variant parameter '" +
                              std::string(name) + "' " + problem);
}
}  // namespace detail

}  // namespace tb::techniques
