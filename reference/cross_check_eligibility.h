// Where Embree's subdivision rules and OpenSubdiv's agree, so that Embree can serve
// as an independent cross-check of the Bfr reference (docs/ARCHITECTURE.md §7).
#pragma once

#include <string>

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"

namespace tb::ref {

// "" when Embree and OpenSubdiv define the same limit surface for this mesh (to Embree's
// float precision), else the first reason they may not, in words: a Loop mesh; a face of
// more than 15 corners; holes, non-manifold edges, interior valence-2 vertices, Chaikin
// creases, valence-2 boundary corners under edge-only interpolation; infinitely sharp tags
// (Embree approximates them after 10 levels); semi-sharp features meeting under different
// rules in Sdc and Embree (cross_check_eligibility.cpp gives the cases and measurements).
std::string crossCheckIneligibility(const mesh::Mesh& mesh, osd::Scheme scheme);

}  // namespace tb::ref
