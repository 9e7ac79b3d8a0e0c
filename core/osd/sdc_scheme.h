// Internal: tessbench's scheme as OpenSubdiv's Sdc::SchemeType.
#pragma once

#include <opensubdiv/sdc/types.h>

#include "core/osd/scheme.h"

namespace tb::osd {

inline OpenSubdiv::Sdc::SchemeType sdcScheme(Scheme scheme) {
  return scheme == Scheme::kLoop ? OpenSubdiv::Sdc::SCHEME_LOOP : OpenSubdiv::Sdc::SCHEME_CATMARK;
}

}  // namespace tb::osd
