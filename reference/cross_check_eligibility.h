// Where Embree's subdivision rules and OpenSubdiv's agree, so that Embree can serve
// as an independent cross-check of the Bfr reference (docs/ARCHITECTURE.md §7).
#pragma once

#include <string>

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"

namespace tb::ref {

// "" when Embree and OpenSubdiv define the same limit surface for this mesh (to
// Embree's float precision), else the first reason they may not, in words:
//  - a Loop mesh (Embree subdivision is Catmull-Clark only);
//  - a face with more than 15 corners (Embree's limit);
//  - holes, non-manifold edges, interior valence-2 vertices, Chaikin creases, and
//    valence-2 boundary corners under edge-only interpolation (the rule sets differ);
//  - infinitely sharp creases or corners (sharpness >= 10), which Embree approximates
//    after 10 levels of refinement;
//  - where semi-sharp features meet with different rules in Sdc and Embree:
//    creases of unequal sharpness at a vertex, a fractional sharpness where three or
//    more sharp edges (boundary edges included) meet, or a fractional corner less
//    sharp than a crease or boundary edge at its vertex (cross_check_eligibility.cpp gives the
//    measurements).
std::string crossCheckIneligibility(const mesh::Mesh& mesh, osd::Scheme scheme);

}  // namespace tb::ref
