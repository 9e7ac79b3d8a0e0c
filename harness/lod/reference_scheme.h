// The subdivision scheme of the limit a technique is graded against (core/osd/scheme.h),
// from the scheme its patches approximate (techniques/technique.h). Shared by the screen
// metrics here and by the error and adaptivity measures above (harness/measures/).
#pragma once

#include "core/osd/scheme.h"
#include "techniques/technique.h"

namespace tb::lod {

// The scheme of the limit a technique is graded against: the one its patches approximate.
inline osd::Scheme referenceScheme(techniques::LimitScheme scheme) {
  return scheme == techniques::LimitScheme::kLoop ? osd::Scheme::kLoop : osd::Scheme::kCatmullClark;
}

}  // namespace tb::lod
