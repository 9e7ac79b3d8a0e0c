// The subdivision scheme of the limit a technique is graded against (reference/scheme.h),
// from the scheme its patches approximate (techniques/technique.h). Shared by the screen
// metrics here and by the error and adaptivity measures above (harness/measures/).
#pragma once

#include "reference/scheme.h"
#include "techniques/technique.h"

namespace tb {

// The scheme of the limit a technique is graded against: the one its patches approximate.
inline ref::Scheme referenceScheme(LimitScheme scheme) {
  return scheme == LimitScheme::kLoop ? ref::Scheme::kLoop : ref::Scheme::kCatmullClark;
}

}  // namespace tb
