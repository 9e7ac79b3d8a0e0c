#include "techniques/common/curvature_bounds.h"

namespace tb::techniques {

std::optional<CurvatureBounds> curvatureBoundsFromNet(const PatchCullBounds& bounds,
                                                      PatchDomain domain) {
  (void)bounds;
  (void)domain;
  return std::nullopt;  // TODO(issue 37): the Bernstein bounds
}

}  // namespace tb::techniques
