// Internal: tessbench's scheme as OpenSubdiv's Sdc::SchemeType.
#pragma once

#include <opensubdiv/sdc/types.h>

#include "reference/scheme.h"

namespace tb::ref {

inline OpenSubdiv::Sdc::SchemeType sdcScheme(Scheme scheme) {
  return scheme == Scheme::kLoop ? OpenSubdiv::Sdc::SCHEME_LOOP : OpenSubdiv::Sdc::SCHEME_CATMARK;
}

}  // namespace tb::ref
