#include "techniques/common/crease_refinement.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/sdc/crease.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/mesh/input_error.h"
#include "core/osd/topology_refiner_builder.h"
#include "techniques/technique.h"

namespace tb::techniques {
namespace {

namespace Far = OpenSubdiv::Far;

const float kInfinite = OpenSubdiv::Sdc::Crease::SHARPNESS_INFINITE;  // 10

// A point for Far::PrimvarRefinerReal<double>.
struct RefinedPoint {
  mesh::Vec3d p{};
  void Clear(void* = nullptr) { p = mesh::Vec3d{}; }
  void AddWithWeight(const RefinedPoint& src, double weight) { p = p + src.p * weight; }
};

bool finite(float sharpness) { return sharpness > 0 && sharpness < kInfinite; }

// Largest finite sharpness of a level's edges and vertices (0 when none).
float largestFiniteSharpness(const Far::TopologyLevel& level) {
  float largest = 0;
  for (int e = 0; e < level.GetNumEdges(); ++e) {
    if (finite(level.GetEdgeSharpness(e))) largest = std::max(largest, level.GetEdgeSharpness(e));
  }
  for (int v = 0; v < level.GetNumVertices(); ++v) {
    if (finite(level.GetVertexSharpness(v)))
      largest = std::max(largest, level.GetVertexSharpness(v));
  }
  return largest;
}

// Faces after `levels` uniform steps: every n-gon becomes n quads, then 4 per step.
size_t facesAfter(const mesh::Mesh& mesh, int levels) {
  if (levels == 0) return mesh.faceCount();
  size_t faces = mesh.face_offsets.back();
  for (int l = 1; l < levels; ++l) faces *= 4;
  return faces;
}

std::unique_ptr<Far::TopologyRefiner> buildRefiner(const mesh::Mesh& mesh,
                                                   const std::string& technique) {
  try {
    return osd::buildTopologyRefiner(mesh, osd::Scheme::kCatmullClark);
  } catch (const mesh::InputError& error) {
    throw UnsupportedInput(technique + ": OpenSubdiv refuses " + mesh.source + ": " + error.what());
  }
}

// Refines `levels` uniform steps (full topology at the last) and returns the last level's
// positions: the input's when `levels` is 0.
std::vector<RefinedPoint> refinePositions(Far::TopologyRefiner& refiner, const mesh::Mesh& mesh,
                                          int levels) {
  std::vector<RefinedPoint> points(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) points[v].p = mesh.positions[v];
  if (levels > 0) {
    Far::TopologyRefiner::UniformOptions options(levels);
    options.fullTopologyInLastLevel = true;  // edges and their sharpness at the last level
    refiner.RefineUniform(options);
    Far::PrimvarRefinerReal<double> primvar(refiner);
    for (int level = 1; level <= levels; ++level) {
      std::vector<RefinedPoint> finer(size_t(refiner.GetLevel(level).GetNumVertices()));
      RefinedPoint* destination = finer.data();
      primvar.Interpolate(level, points.data(), destination);
      points = std::move(finer);
    }
  }
  return points;
}

// Input face of every face of the last level, through the parent chain.
std::vector<uint32_t> inputFaces(const Far::TopologyRefiner& refiner, int levels) {
  const int face_count = refiner.GetLevel(levels).GetNumFaces();
  std::vector<uint32_t> source_of(static_cast<size_t>(face_count));
  for (int f = 0; f < face_count; ++f) {
    int face = f;
    for (int level = levels; level > 0; --level)
      face = refiner.GetLevel(level).GetFaceParentFace(face);
    source_of[size_t(f)] = uint32_t(face);
  }
  return source_of;
}

// The control mesh: faces with a limit surface first, then the holes.
void buildControlMesh(const mesh::Mesh& mesh, const Far::TopologyLevel& last,
                      const std::vector<RefinedPoint>& points,
                      const std::vector<uint32_t>& source_of, CreasePreparation& out) {
  const int face_count = last.GetNumFaces();
  mesh::Mesh& control = out.control;
  control.source = mesh.source;
  for (const RefinedPoint& p : points) control.positions.push_back(p.p);
  if (out.levels == 0) {
    control.normals = mesh.normals;
    control.uvs = mesh.uvs;
    control.normals_computed = mesh.normals_computed;
  }
  control.tags.boundary = mesh.tags.boundary;
  control.tags.boundary_from_tag = mesh.tags.boundary_from_tag;
  control.tags.crease_method = mesh.tags.crease_method;
  control.tags.smooth_triangles = mesh.tags.smooth_triangles;
  std::vector<int> order;
  for (int f = 0; f < face_count; ++f) {
    if (!last.IsFaceHole(f)) order.push_back(f);
  }
  out.patch_faces = order.size();
  for (int f = 0; f < face_count; ++f) {
    if (last.IsFaceHole(f)) order.push_back(f);
  }
  for (size_t i = 0; i < order.size(); ++i) {
    const int f = order[i];
    const uint32_t input_face = source_of[size_t(f)];
    const uint32_t line = input_face < mesh.face_lines.size() ? mesh.face_lines[input_face] : 0;
    const Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    const std::vector<uint32_t> corners(vertices.begin(), vertices.end());
    if (out.levels == 0) {  // keep the input's normal and uv indices
      const uint32_t first = mesh.face_offsets[size_t(f)], size = mesh.faceSize(size_t(f));
      control.addFace(corners, {mesh.corner_normals.data() + first, size},
                      {mesh.corner_uvs.data() + first, size}, line);
    } else {
      control.addFace(corners, {}, {}, line);
    }
    out.source_face.push_back(input_face);
    if (i >= out.patch_faces) control.tags.holes.push_back(uint32_t(i));
  }
}

// The last level's edges: crease tags (true values, for the reference) and the sharp edges
// the patches honour (finite leftovers rounded). Returns the sharp edges at each vertex.
// Boundary edges are tagged only under boundary interpolation none (Far reports every
// boundary edge infinitely sharp): there a face at the boundary has a limit surface only
// where the boundary edges at its vertices were tagged sharp (Far's holes at level 0, Bfr's
// FaceHasLimitSurface), and with the tags dropped Bfr over the control mesh would deny a limit
// to faces the patches cover. With every boundary edge tagged, the faces without a limit are
// exactly the holes listed; the rules are unchanged (boundary edges are sharp under any rule).
std::vector<uint32_t> tagEdges(const mesh::Mesh& mesh, const Far::TopologyLevel& last,
                               CreasePreparation& out) {
  mesh::Mesh& control = out.control;
  const bool boundary_sharp = mesh.tags.boundary != mesh::BoundaryInterpolation::kNone;
  std::vector<uint32_t> sharp_count(control.positions.size(), 0);
  for (int e = 0; e < last.GetNumEdges(); ++e) {
    const Far::ConstIndexArray ends = last.GetEdgeVertices(e);
    const uint32_t a = uint32_t(ends[0]), b = uint32_t(ends[1]);
    const float sharpness = last.GetEdgeSharpness(e);
    const bool boundary = last.GetEdgeFaces(e).size() == 1;
    if (sharpness > 0 && (!boundary || !boundary_sharp))
      control.tags.creases.push_back({a, b, double(sharpness)});
    if (finite(sharpness) && !boundary)
      out.rounded_sharpness = std::max(out.rounded_sharpness, double(sharpness));
    if (sharpness >= 0.5f || (boundary && boundary_sharp)) {
      out.sharp_edges.insert(CreasePreparation::sharpEdgeKey(a, b));
      ++sharp_count[a];
      ++sharp_count[b];
    }
  }
  return sharp_count;
}

// The last level's vertices: corner tags and each vertex's kind as the patches see it.
void tagVertices(const mesh::Mesh& mesh, const Far::TopologyLevel& last,
                 const std::vector<uint32_t>& sharp_count, CreasePreparation& out) {
  mesh::Mesh& control = out.control;
  out.vertex_kind.assign(control.positions.size(), SharpVertexKind::kSmooth);
  for (int v = 0; v < last.GetNumVertices(); ++v) {
    const float sharpness = last.GetVertexSharpness(v);
    const size_t faces = size_t(last.GetVertexFaces(v).size());
    const bool boundary = size_t(last.GetVertexEdges(v).size()) > faces;
    if (sharpness > 0) control.tags.corners.push_back({uint32_t(v), double(sharpness)});
    if (finite(sharpness))
      out.rounded_sharpness = std::max(out.rounded_sharpness, double(sharpness));
    const uint32_t count = sharp_count[size_t(v)];
    // A leftover finite vertex sharpness off a crease is rounded to smooth: no patch here
    // represents a cone point, and the tag would have decayed in a few more levels.
    bool sharp_vertex = sharpness >= kInfinite || (sharpness >= 0.5f && count >= 2);
    // Edge-and-corner interpolation makes a boundary vertex of one face a corner.
    if (boundary && faces == 1 &&
        mesh.tags.boundary == mesh::BoundaryInterpolation::kEdgeAndCorner) {
      sharp_vertex = true;
    }
    SharpVertexKind kind = SharpVertexKind::kSmooth;
    if (sharp_vertex) {
      kind = count >= 2 ? SharpVertexKind::kCorner : SharpVertexKind::kCone;
    } else if (count >= 3) {
      kind = SharpVertexKind::kCorner;
    } else if (count == 2) {
      kind = SharpVertexKind::kCrease;
    } else if (count == 1) {
      kind = SharpVertexKind::kDart;
    }
    out.vertex_kind[size_t(v)] = kind;
  }
}

// The instance's warnings: levels refined against the budget, sharpness rounded, holes.
void addNotes(size_t max_faces, CreasePreparation& out) {
  const mesh::Mesh& control = out.control;
  if (out.levels > 0 && out.levels_needed > 0) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "semi-sharp creases: refined %d of %d levels (%zu faces; budget %zu faces)",
                  out.levels, out.levels_needed, control.faceCount(), max_faces);
    out.notes.push_back(line);
  }
  if (out.rounded_sharpness > 0) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "sharpness up to %.3g left after %d levels, rounded (>= 0.5 infinitely sharp, "
                  "below smooth)",
                  out.rounded_sharpness, out.levels);
    out.notes.push_back(line);
  }
  if (out.patch_faces < control.faceCount()) {
    out.notes.push_back(std::to_string(control.faceCount() - out.patch_faces) +
                        " faces without a limit surface (holes) get no patch");
  }
}

}  // namespace

CreasePreparation prepareCreases(const mesh::Mesh& mesh, const std::string& technique,
                                 size_t max_faces, int min_levels) {
  std::unique_ptr<Far::TopologyRefiner> refiner = buildRefiner(mesh, technique);
  CreasePreparation out;
  const float largest = largestFiniteSharpness(refiner->GetLevel(0));
  out.levels_needed = int(std::ceil(largest));
  out.levels = std::max(0, min_levels);
  while (out.levels < out.levels_needed && facesAfter(mesh, out.levels + 1) <= max_faces)
    ++out.levels;

  const std::vector<RefinedPoint> points = refinePositions(*refiner, mesh, out.levels);
  const Far::TopologyLevel& last = refiner->GetLevel(out.levels);
  buildControlMesh(mesh, last, points, inputFaces(*refiner, out.levels), out);
  const std::vector<uint32_t> sharp_count = tagEdges(mesh, last, out);
  tagVertices(mesh, last, sharp_count, out);
  if (out.levels == 0 && out.patch_faces == out.control.faceCount()) {
    out.control.tags = mesh.tags;  // nothing moved: the control mesh is the input as it is
  }
  addNotes(max_faces, out);
  return out;
}

}  // namespace tb::techniques
