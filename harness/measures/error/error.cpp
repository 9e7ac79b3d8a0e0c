#include "harness/measures/error/error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>

#include "core/mesh/input_error.h"
#include "core/mesh/topology.h"
#include "core/osd/scheme.h"
#include "harness/measures/common/patch_sample.h"
#include "harness/measures/error/hausdorff_memo.h"
#include "reference/hausdorff.h"
#include "reference/limit_tessellation.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::measures {
namespace {

struct PatchSample {
  techniques::DomainCoord coord;        // as the technique takes it
  int sub_face = -1;                    // >= 0: (u, v) are the (s, t) of this Bfr sub-face
  double u, v;                          // the limit face's parameter at the same point
  std::array<double, 4> corner_weight;  // weight of each patch corner
};

// The samples of one kind of patch and the triangles over them (indices from 0), for the
// technique's side of the distance.
struct PatchSampling {
  std::vector<PatchSample> samples;
  std::vector<ref::Triangle> triangles;
};

// Triangles over a (level + 1)^2 grid whose point (i, j) is base + i * (level + 1) + j.
void appendGridTriangles(int level, uint32_t base, std::vector<ref::Triangle>* triangles) {
  auto at = [&](int i, int j) { return base + uint32_t(i * (level + 1) + j); };
  for (int i = 0; i < level; ++i) {
    for (int j = 0; j < level; ++j) {
      triangles->push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      triangles->push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
}

// Barycentric lattice (triangles) or grid (quads) of `level` segments per edge, where the
// patch and the limit face share their parameterisation.
PatchSampling patchSampling(techniques::PatchDomain domain, int level) {
  PatchSampling sampling;
  std::vector<PatchSample>& samples = sampling.samples;
  for (int i = 0; i <= level; ++i) {
    const int j_end = domain == techniques::PatchDomain::kQuad ? level : level - i;
    for (int j = 0; j <= j_end; ++j) {
      const double a = double(i) / level, b = double(j) / level;
      if (domain == techniques::PatchDomain::kTriangle) {
        // Bfr's triangle has corners (0,0), (1,0), (0,1): weights (1-u-v, u, v).
        samples.push_back({{1 - a - b, a, b}, -1, a, b, {1 - a - b, a, b, 0}});
      } else {
        samples.push_back(
            {{a, b, 0}, -1, a, b, {(1 - a) * (1 - b), a * (1 - b), a * b, (1 - a) * b}});
      }
    }
  }
  if (domain == techniques::PatchDomain::kQuad) {
    appendGridTriangles(level, 0, &sampling.triangles);
    return sampling;
  }
  // Row i holds level - i + 1 points; index of (i, j) by the row offsets.
  std::vector<uint32_t> row_start(level + 2, 0);
  for (int i = 0; i <= level; ++i) row_start[i + 1] = row_start[i] + uint32_t(level - i + 1);
  auto at = [&](int i, int j) { return row_start[i] + uint32_t(j); };
  for (int i = 0; i < level; ++i) {
    for (int j = 0; j < level - i; ++j) {
      sampling.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (j + 1 < level - i) {
        sampling.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  return sampling;
}

// A triangle patch over a Catmull-Clark triangle, which Bfr parameterises as three quad
// sub-faces (reference/face_domain.h): sub-face k spans corner k, the midpoint of edge k
// (corner k -> k+1), the centroid and the midpoint of edge k-1, with s towards edge k's
// midpoint and t towards edge k-1's. A (level + 1)^2 grid of (s, t) on each sub-face is
// mapped bilinearly through those four points to the patch's barycentric domain.
PatchSampling subFaceSampling(int level) {
  using Bary = std::array<double, 3>;
  auto mix = [](const Bary& a, const Bary& b, double wa, double wb) {
    return Bary{wa * a[0] + wb * b[0], wa * a[1] + wb * b[1], wa * a[2] + wb * b[2]};
  };
  PatchSampling sampling;
  for (int k = 0; k < 3; ++k) {
    Bary corner{0, 0, 0}, next{0, 0, 0}, previous{0, 0, 0};
    corner[k] = next[(k + 1) % 3] = previous[(k + 2) % 3] = 1;
    const Bary quad[4] = {corner,
                          mix(corner, next, 0.5, 0.5),
                          {1.0 / 3, 1.0 / 3, 1.0 / 3},
                          mix(corner, previous, 0.5, 0.5)};
    appendGridTriangles(level, uint32_t(sampling.samples.size()), &sampling.triangles);
    for (int i = 0; i <= level; ++i) {
      for (int j = 0; j <= level; ++j) {
        const double s = double(i) / level, t = double(j) / level;
        const double w[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
        techniques::DomainCoord coord{0, 0, 0};
        for (int q = 0; q < 4; ++q) {
          for (int c = 0; c < 3; ++c) coord[c] += w[q] * quad[q][c];
        }
        sampling.samples.push_back({coord, k, s, t, {coord[0], coord[1], coord[2], 0}});
      }
    }
  }
  return sampling;
}

[[noreturn]] void throwUnmappedDomain(techniques::PatchDomain domain, osd::Scheme scheme,
                                      size_t face, uint32_t face_size) {
  throw std::logic_error("error: patch over face " + std::to_string(face) + " is a " +
                         toString(domain) + " patch, but the face has " +
                         std::to_string(face_size) + " corners under " +
                         std::string(osd::schemeName(scheme)) +
                         "; the measure maps quad patches onto Catmull-Clark faces, and triangle "
                         "patches onto Loop faces or Catmull-Clark triangles");
}

// The sampling of patch p over its limit face; throws std::logic_error for a patch
// domain the face's parameterisation cannot be mapped to.
const PatchSampling& samplingFor(techniques::PatchDomain domain, osd::Scheme scheme, size_t face,
                                 uint32_t face_size,
                                 const std::array<PatchSampling, 3>& samplings) {
  if (domain == techniques::PatchDomain::kQuad && scheme == osd::Scheme::kCatmullClark)
    return samplings[0];
  if (domain == techniques::PatchDomain::kTriangle && scheme == osd::Scheme::kLoop)
    return samplings[1];
  if (domain == techniques::PatchDomain::kTriangle && face_size == 3) return samplings[2];
  throwUnmappedDomain(domain, scheme, face, face_size);
}

double angleDegrees(const mesh::Vec3d& a, const mesh::Vec3d& b) {
  const double la = length(a), lb = length(b);
  if (!(la > 0) || !(lb > 0)) return 0;
  return std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// The inverse of subFaceSampling's map on sub-face k, whose corners in barycentric
// coordinates are corner k, the midpoints of edges k and k-1 and the centroid. With a, b the
// weights of corners k+1 and k+2, the map is a = s (3 - t) / 6, b = t (3 - s) / 6, so
// s - t = 2 (a - b) = d and t is the root in [0, 1] of t^2 + (d - 3) t + 6 b = 0, taken in the
// form without cancellation (12 b / ((3 - d) + sqrt(disc))).
LimitParameter subFaceParameter(const techniques::DomainCoord& coord) {
  int k = 0;
  for (int c = 1; c < 3; ++c) {
    if (coord[c] > coord[k]) k = c;
  }
  const double a = coord[(k + 1) % 3], b = coord[(k + 2) % 3];
  const double d = 2 * (a - b);
  const double disc = std::max(0.0, (3 - d) * (3 - d) - 24 * b);
  const double t = 12 * b / ((3 - d) + std::sqrt(disc));
  return {k, std::clamp(t + d, 0.0, 1.0), std::clamp(t, 0.0, 1.0)};
}

}  // namespace

LimitParameter limitParameterOf(techniques::PatchDomain domain, osd::Scheme scheme, size_t face,
                                uint32_t face_size, const techniques::DomainCoord& coord) {
  if (domain == techniques::PatchDomain::kQuad && scheme == osd::Scheme::kCatmullClark) {
    return {-1, coord[0], coord[1]};
  }
  if (domain == techniques::PatchDomain::kTriangle && scheme == osd::Scheme::kLoop) {
    return {-1, coord[1], coord[2]};
  }
  if (domain == techniques::PatchDomain::kTriangle && face_size == 3)
    return subFaceParameter(coord);
  throwUnmappedDomain(domain, scheme, face, face_size);
}

double parametricErrorAt(const techniques::SurfacePatches& patches, const ref::LimitFace& face,
                         osd::Scheme scheme, size_t patch, const techniques::DomainCoord& coord) {
  const LimitParameter at = limitParameterOf(patches.patchDomain(patch), scheme, patch,
                                             patches.controlMesh().faceSize(patch), coord);
  const ref::LimitPoint exact =
      at.sub_face < 0 ? face.evaluate(at.u, at.v) : face.evaluateSubFace(at.sub_face, at.u, at.v);
  return length(patches.evaluate(patch, coord).position - exact.position);
}

std::vector<uint8_t> facesTouchingCreases(const mesh::Mesh& mesh) {
  std::vector<uint8_t> creased_vertex(mesh.positions.size(), 0);
  for (const mesh::Crease& crease : mesh.tags.creases) {
    if (crease.sharpness <= 0) continue;
    for (uint32_t v : {crease.v0, crease.v1}) {
      if (v < creased_vertex.size()) creased_vertex[v] = 1;
    }
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    if (corner.sharpness > 0 && corner.vertex < creased_vertex.size())
      creased_vertex[corner.vertex] = 1;
  }
  std::vector<uint8_t> touching(mesh.faceCount(), 0);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    for (uint32_t v : mesh.facePositions(f)) touching[f] |= creased_vertex[v];
  }
  return touching;
}

namespace {

// Where each patch's samples start in the flat sample arrays (patches without a limit
// have none), so patches can be sampled in parallel into fixed slots; the figures are
// then reduced serially in sample order, so they do not depend on the thread count.
struct SamplePlan {
  std::vector<const PatchSampling*> sampling_of;  // null: no limit surface
  std::vector<size_t> first_sample;               // patch count + 1 entries
  size_t sampleCount() const { return first_sample.back(); }
};

SamplePlan planSamples(const techniques::SurfacePatches& patches, const ref::LimitSurface& limit,
                       osd::Scheme scheme, const std::array<PatchSampling, 3>& samplings,
                       SurfaceErrorFigures* figures) {
  const mesh::Mesh& control = patches.controlMesh();
  const size_t patch_count = patches.patchCount();
  SamplePlan plan{std::vector<const PatchSampling*>(patch_count, nullptr),
                  std::vector<size_t>(patch_count + 1, 0)};
  for (size_t p = 0; p < patch_count; ++p) {
    if (limit.hasLimitSurface(p)) {
      plan.sampling_of[p] =
          &samplingFor(patches.patchDomain(p), scheme, p, control.faceSize(p), samplings);
      figures->patches_through_sub_faces += plan.sampling_of[p] == &samplings[2];
    } else {
      ++figures->patches_without_limit;
    }
    plan.first_sample[p + 1] =
        plan.first_sample[p] + (plan.sampling_of[p] ? plan.sampling_of[p]->samples.size() : 0);
  }
  return plan;
}

// Per sample, in plan order: the technique's point, its parametric error (world units),
// the normal angle (degrees), and whether it is near an extraordinary vertex.
struct SampleValues {
  std::vector<mesh::Vec3d> technique_points;
  std::vector<double> errors, angles;
  std::vector<uint8_t> near_xord;
};

// 1 per control-mesh position at an extraordinary vertex of the scheme.
std::vector<uint8_t> extraordinaryVertices(const mesh::Mesh& control,
                                           const mesh::Topology& topology, osd::Scheme scheme) {
  const uint32_t regular_valence = scheme == osd::Scheme::kCatmullClark ? 4 : 6;
  std::vector<uint8_t> extraordinary(control.positions.size(), 0);
  for (uint32_t v : topology.extraordinaryVertices(regular_valence)) extraordinary[v] = 1;
  return extraordinary;
}

SampleValues evaluateSamples(const techniques::SurfacePatches& patches,
                             const ref::LimitSurface& limit, const SamplePlan& plan,
                             const std::vector<uint8_t>& extraordinary) {
  const size_t sample_count = plan.sampleCount();
  SampleValues values{std::vector<mesh::Vec3d>(sample_count), std::vector<double>(sample_count),
                      std::vector<double>(sample_count), std::vector<uint8_t>(sample_count)};
  tbb::parallel_for(size_t(0), patches.patchCount(), [&](size_t p) {
    if (plan.sampling_of[p] == nullptr) return;
    const ref::LimitFace face = limit.face(p);
    const auto corners = patches.patchCorners(p);
    size_t i = plan.first_sample[p];
    for (const PatchSample& sample : plan.sampling_of[p]->samples) {
      const techniques::SurfacePoint point = patches.evaluate(p, sample.coord);
      const ref::LimitPoint exact = sample.sub_face < 0
                                        ? face.evaluate(sample.u, sample.v)
                                        : face.evaluateSubFace(sample.sub_face, sample.u, sample.v);
      values.technique_points[i] = point.position;
      values.errors[i] = length(point.position - exact.position);
      bool near = false;
      for (int c = 0; c < 4; ++c) {
        near |= corners[c] != UINT32_MAX && extraordinary[corners[c]] &&
                sample.corner_weight[c] >= kNearExtraordinary;
      }
      values.near_xord[i] = near;
      values.angles[i] = angleDegrees(point.normal, exact.normal);
      ++i;
    }
  });
  return values;
}

// The technique's side of the distance: every sampled patch's triangles, indexing the
// plan's flat sample order.
std::vector<ref::Triangle> techniqueTriangles(const SamplePlan& plan,
                                              const std::vector<uint8_t>& patch_in) {
  std::vector<ref::Triangle> triangles;
  for (size_t p = 0; p + 1 < plan.first_sample.size(); ++p) {
    if (plan.sampling_of[p] == nullptr || !patch_in[p]) continue;
    const uint32_t base = uint32_t(plan.first_sample[p]);
    for (const ref::Triangle& triangle : plan.sampling_of[p]->triangles) {
      triangles.push_back({base + triangle[0], base + triangle[1], base + triangle[2]});
    }
  }
  return triangles;
}

// 1 for each sample of a patch whose input face touches a crease.
// 1 for each patch whose input face touches a crease.
std::vector<uint8_t> creasedPatches(const techniques::SurfacePatches& patches,
                                    const mesh::Mesh* input) {
  const std::vector<uint8_t> creased_face =
      facesTouchingCreases(input ? *input : patches.controlMesh());
  std::vector<uint8_t> creased(patches.patchCount(), 0);
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const size_t face = input ? patches.sourceFace(p) : p;
    creased[p] = face < creased_face.size() && creased_face[face] != 0;
  }
  return creased;
}

std::vector<uint8_t> creasedSamples(const techniques::SurfacePatches& patches,
                                    const std::vector<uint8_t>& creased, const SamplePlan& plan) {
  std::vector<uint8_t> crease_of_sample(plan.sampleCount(), 0);
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    if (creased[p]) {
      std::fill(crease_of_sample.begin() + ptrdiff_t(plan.first_sample[p]),
                crease_of_sample.begin() + ptrdiff_t(plan.first_sample[p + 1]), uint8_t(1));
    }
  }
  return crease_of_sample;
}

// The patches the Hausdorff figures sample (error.h, kErrorHausdorffPatchBudget): `part`, the
// sampled patches; `around`, those and every patch sharing a vertex with one (the surface a
// closest point can fall on); `all` when every patch with a limit is in `part`.
struct HausdorffPatches {
  std::vector<uint8_t> part, around;
  size_t count = 0;
  bool all = true;
};

HausdorffPatches hausdorffPatches(const techniques::SurfacePatches& patches, const SamplePlan& plan,
                                  const mesh::Topology& topology,
                                  const std::vector<uint8_t>& extraordinary,
                                  const std::vector<uint8_t>& creased,
                                  const HausdorffSampling& sampling) {
  const size_t budget = sampling.patch_budget;
  const mesh::Mesh& control = patches.controlMesh();
  const size_t patch_count = patches.patchCount();
  HausdorffPatches out{std::vector<uint8_t>(patch_count, 0), {}, 0, true};
  std::vector<uint8_t> next_to_hole(control.positions.size(), 0);
  for (size_t p = 0; p < patch_count; ++p) {
    if (plan.sampling_of[p] == nullptr) {
      for (uint32_t v : control.facePositions(p)) next_to_hole[v] = 1;
    }
  }
  std::vector<uint8_t> feature(patch_count, 0), has_limit(patch_count, 0);
  for (size_t p = 0; p < patch_count; ++p) {
    if (plan.sampling_of[p] == nullptr) continue;
    has_limit[p] = 1;
    feature[p] = creased[p] != 0;
    for (uint32_t v : control.facePositions(p)) {
      feature[p] |= extraordinary[v] || topology.on_boundary[v] || next_to_hole[v];
    }
  }
  PatchSubset sample = samplePatches(feature, has_limit, budget, sampling.keep_feature_patches);
  out.part = std::move(sample.part);
  out.count = sample.count;
  out.all = sample.all;
  out.around = out.part;
  if (out.all) return out;
  std::vector<uint8_t> touched(control.positions.size(), 0);
  for (size_t p = 0; p < patch_count; ++p) {
    if (!out.part[p]) continue;
    for (uint32_t v : control.facePositions(p)) touched[v] = 1;
  }
  for (size_t p = 0; p < patch_count; ++p) {
    for (uint32_t v : control.facePositions(p)) out.around[p] |= touched[v];
  }
  return out;
}

// The parametric and normal figures (world units), reduced serially in sample order.
void reduceSamples(const SampleValues& values, const std::vector<uint8_t>& crease_of_sample,
                   SurfaceErrorFigures* figures) {
  double squared_sum = 0, normal_sum = 0;
  for (size_t i = 0; i < values.errors.size(); ++i) {
    const double error = values.errors[i];
    double& bucket =
        values.near_xord[i] ? figures->parametric_max_near_xord : figures->parametric_max_elsewhere;
    bucket = std::max(bucket, error);
    const bool near_crease = crease_of_sample[i] != 0;
    double& crease_bucket = near_crease ? figures->parametric_max_near_crease
                                        : figures->parametric_max_away_from_crease;
    crease_bucket = std::max(crease_bucket, error);
    figures->samples_near_crease += near_crease;
    figures->samples_near_xord += values.near_xord[i];
    figures->parametric_max = std::max(figures->parametric_max, error);
    squared_sum += error * error;
    figures->normal_max_deg = std::max(figures->normal_max_deg, values.angles[i]);
    normal_sum += values.angles[i];
    ++figures->samples;
  }
  if (figures->samples > 0) {
    figures->parametric_rms = std::sqrt(squared_sum / double(figures->samples));
    figures->normal_mean_deg = normal_sum / double(figures->samples);
  }
}

// Relative to the bounding-box diagonal, as every error figure is reported.
void scaleByDiagonal(SurfaceErrorFigures* figures) {
  const double scale = figures->bbox_diagonal > 0 ? 1 / figures->bbox_diagonal : 0;
  for (double* value :
       {&figures->parametric_max, &figures->parametric_rms, &figures->parametric_max_near_xord,
        &figures->parametric_max_elsewhere, &figures->parametric_max_near_crease,
        &figures->parametric_max_away_from_crease, &figures->hausdorff,
        &figures->hausdorff_technique_to_limit, &figures->hausdorff_limit_to_technique,
        &figures->rms_distance}) {
    *value *= scale;
  }
}

}  // namespace

SurfaceErrorFigures measureSurfaceError(const techniques::SurfacePatches& patches,
                                        const ref::LimitSurface& limit, const mesh::Mesh* input,
                                        HausdorffSampling sampling) {
  const osd::Scheme scheme = lod::referenceScheme(patches.approximates());
  if (limit.scheme() != scheme) {
    throw std::logic_error("error: the patches approximate " +
                           std::string(osd::schemeName(scheme)) + " but the limit surface is " +
                           std::string(osd::schemeName(limit.scheme())));
  }
  SurfaceErrorFigures figures;
  figures.bbox_diagonal = ref::boundingBoxDiagonal(patches.controlMesh().positions);
  const std::array<PatchSampling, 3> samplings = {
      patchSampling(techniques::PatchDomain::kQuad, kErrorSampleLevel),
      patchSampling(techniques::PatchDomain::kTriangle, kErrorSampleLevel),
      subFaceSampling(kErrorSubFaceSampleLevel)};
  const SamplePlan plan = planSamples(patches, limit, scheme, samplings, &figures);
  const mesh::Mesh& control = patches.controlMesh();
  const mesh::Topology topology = mesh::buildTopology(control);
  const std::vector<uint8_t> extraordinary = extraordinaryVertices(control, topology, scheme);
  const std::vector<uint8_t> creased = creasedPatches(patches, input);
  const SampleValues values = evaluateSamples(patches, limit, plan, extraordinary);
  reduceSamples(values, creasedSamples(patches, creased, plan), &figures);
  if (figures.samples > 0) {
    const HausdorffPatches part =
        hausdorffPatches(patches, plan, topology, extraordinary, creased, sampling);
    figures.hausdorff_patches = part.count;
    // With every patch in the sample, part and around are one mesh: built once.
    const std::vector<ref::Triangle> technique_around = techniqueTriangles(plan, part.around);
    const std::vector<ref::Triangle> technique_part =
        part.all ? std::vector<ref::Triangle>() : techniqueTriangles(plan, part.part);
    const ref::LimitTessellation dense = ref::tessellateLimit(
        limit, kErrorReferenceRate, part.all ? std::span<const uint8_t>() : part.around);
    std::vector<ref::Triangle> dense_part;
    for (size_t t = 0; t < dense.triangles.size() && !part.all; ++t) {
      if (part.part[dense.triangle_face[t]]) dense_part.push_back(dense.triangles[t]);
    }
    const ref::HausdorffResult distance = memoisedHausdorff(
        {values.technique_points, part.all ? technique_around : technique_part},
        {values.technique_points, technique_around},
        part.all ? dense.view() : ref::TriangleMeshRef{dense.positions, dense_part}, dense.view(),
        2);
    figures.hausdorff = distance.hausdorff;
    figures.hausdorff_technique_to_limit = distance.a_to_b.max;
    figures.hausdorff_limit_to_technique = distance.b_to_a.max;
    figures.rms_distance = distance.rms;
  }
  scaleByDiagonal(&figures);
  return figures;
}

}  // namespace tb::measures
