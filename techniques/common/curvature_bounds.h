// Second-derivative bounds (CurvatureBounds, techniques/technique.h) of polynomial patches
// in Bernstein form: a Bezier net's second differences bound its second derivatives (the
// derivative of a Bernstein polynomial is a Bernstein polynomial of the differences, and a
// Bernstein polynomial lies in the hull of its coefficients).
#pragma once

#include <optional>

#include "techniques/technique.h"

namespace tb::techniques {

// The bounds of the polynomial patch cullBounds() describes (PatchCullBounds::bezier_net of
// bezier_degree on `domain`), or nullopt when it gives no net.
std::optional<CurvatureBounds> curvatureBoundsFromNet(const PatchCullBounds& bounds,
                                                      PatchDomain domain);

}  // namespace tb::techniques
