// Error (docs/MEASURES.md) of a surface technique against the exact limit
// surface of its control mesh (OpenSubdiv Bfr, in double).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "harness/lod/reference_scheme.h"
#include "reference/limit_surface.h"
#include "techniques/technique.h"

namespace tb::measures {

// Every distance is a fraction of the control mesh's bounding-box diagonal
// (best case 0; a visible error on a 1000-pixel-wide object starts near 1e-3).
struct SurfaceErrorFigures {
  double bbox_diagonal = 0;  // world units
  // |S(p, u, v) - limit(face(p), u, v)| at the same parameter.
  double parametric_max = 0;
  double parametric_rms = 0;
  double parametric_max_near_xord = 0;  // samples near an extraordinary vertex (kNearExtraordinary)
  double parametric_max_elsewhere = 0;
  // Samples on patches whose input face touches a crease (an edge of crease sharpness > 0 or
  // a vertex of corner sharpness > 0 in the input's tags), and the others. A creased input
  // refined by the technique (techniques/common/crease_refinement.h) keeps the input face
  // of every refined face (SurfacePatches::sourceFace).
  double parametric_max_near_crease = 0;
  double parametric_max_away_from_crease = 0;
  // Two-sided distance between the technique's tessellation and a dense
  // tessellation of the limit, sampled inside triangles.
  double hausdorff = 0;
  double hausdorff_technique_to_limit = 0;
  double hausdorff_limit_to_technique = 0;
  double rms_distance = 0;
  // Angle between the technique's shading normal and the limit normal at the same
  // parameter, in degrees (best 0, worst 180).
  double normal_max_deg = 0;
  double normal_mean_deg = 0;
  size_t samples = 0;  // parametric samples taken
  size_t samples_near_xord = 0;
  size_t samples_near_crease = 0;
  size_t patches_without_limit = 0;  // hole faces etc., left out
  // Triangle patches over Catmull-Clark triangles, sampled through Bfr's quad sub-faces
  // (kErrorSubFaceSampleLevel); 0 for single-scheme techniques.
  size_t patches_through_sub_faces = 0;
  // Patches whose surfaces the Hausdorff figures sampled: every patch with a limit (exact), or
  // the sample of kErrorHausdorffPatchBudget on a larger asset.
  size_t hausdorff_patches = 0;
};

// Patches with a limit above which the Hausdorff figures (hausdorff*, rms_distance) sample
// patches; the parametric and normal figures never do. Every bundled asset is below it. The
// sample: every feature patch (a corner at an extraordinary or boundary vertex or next to a
// hole, or its input face touching a crease: where techniques err most), then runs of 16
// consecutive other patches, evenly spaced in patch order, up to the budget. Its distances go to
// the other surface over the sampled patches and their vertex neighbours (where a closest point
// falls), so the sampled Hausdorff distance is the largest over the sample: never above the full
// one, and equal to it when the worst patch is sampled (tests/measures/error_test.cpp bounds it on
// the bundled assets). A production-size asset's dense reference is then a few million triangles,
// not tens of millions (a 25k-patch asset at rate 16 is 12.8 million).
inline constexpr size_t kErrorHausdorffPatchBudget = 2048;

// Lattice level of the technique's sampling (per patch edge) and the rate of the
// reference tessellation.
constexpr int kErrorSampleLevel = 8;
constexpr int kErrorReferenceRate = 16;
// Segments per sub-face edge for a triangle patch sampled through the three quad
// sub-faces Bfr gives a Catmull-Clark triangle: 3 (4 + 1)^2 = 75 samples, against 45 on a
// Loop triangle and 81 on a quad.
constexpr int kErrorSubFaceSampleLevel = kErrorSampleLevel / 2;
// A sample is "near" an extraordinary vertex when its barycentric weight (or
// bilinear weight, for quads) of that corner is at least this.
constexpr double kNearExtraordinary = 0.75;

// referenceScheme (the scheme of the limit a technique is graded against) lives in
// harness/lod/reference_scheme.h, included here.

// The limit surface must be built over patches.controlMesh(), whose face p is patch p,
// under the scheme patches.approximates() names. Each patch is sampled in its own
// patchDomain(p): quads on Catmull-Clark faces, triangles on Loop faces share the face's
// parameterisation; triangles on Catmull-Clark triangles go through the sub-face map
// (subFaceSampling in the .cpp). Throws std::logic_error for a scheme mismatch or any other
// combination.
// `input`: the mesh the technique was built from, whose tags say which samples are near a
// crease; null: the control mesh's own tags.
// How the Hausdorff figures sample patches: the measure's rule by default. Tests vary the
// budget (SIZE_MAX: never sample) and turn the feature patches off for their broken control.
struct HausdorffSampling {
  size_t patch_budget = kErrorHausdorffPatchBudget;
  bool keep_feature_patches = true;  // false: runs only (a control, never the measure's)
};
SurfaceErrorFigures measureSurfaceError(const techniques::SurfacePatches& patches,
                                        const ref::LimitSurface& limit,
                                        const mesh::Mesh* input = nullptr,
                                        HausdorffSampling sampling = {});

// Per face of `mesh`: 1 when the face touches a crease (an edge of crease sharpness > 0 or a
// vertex of corner sharpness > 0).
std::vector<uint8_t> facesTouchingCreases(const mesh::Mesh& mesh);

// The point of the limit face (face_domain.h) at which a patch's domain coordinate is
// graded: the same parameter for quads on Catmull-Clark faces ((u, v) = coord[0], coord[1])
// and triangles on Loop faces ((u, v) = coord[1], coord[2], the weights of corners 1 and 2);
// for a triangle patch on a Catmull-Clark triangle, the inverse of the bilinear sub-face map
// measureSurfaceError samples through (sub-face k where corner k has the largest weight,
// ties to the lower k).
struct LimitParameter {
  int sub_face = -1;  // >= 0: (u, v) are the normalised (s, t) of this Bfr sub-face
  double u = 0, v = 0;
};

// Throws std::logic_error, as measureSurfaceError does, for a domain the face's
// parameterisation cannot be mapped to. `face_size`: corners of control face `face`.
LimitParameter limitParameterOf(techniques::PatchDomain domain, osd::Scheme scheme, size_t face,
                                uint32_t face_size, const techniques::DomainCoord& coord);

// One parametric-error sample of patch p at `coord`, in world units (divide by the
// bounding-box diagonal for the figures' unit): |S(p, coord) - limit(face(p), same point)|,
// S from patches.evaluate (double), the point from limitParameterOf. Best case 0 (acc on a
// regular face: ~1e-16 of the diagonal). `face` is limit.face(p) of a LimitSurface built as
// for measureSurfaceError.
double parametricErrorAt(const techniques::SurfacePatches& patches, const ref::LimitFace& face,
                         osd::Scheme scheme, size_t patch, const techniques::DomainCoord& coord);

}  // namespace tb::measures
