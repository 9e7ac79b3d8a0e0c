#include "core/osd/topology_refiner_builder.h"

#include <opensubdiv/far/topologyDescriptor.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "core/osd/far_error_capture.h"
#include "core/osd/sdc_scheme.h"

namespace tb::osd {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

void checkSharpness(const mesh::Mesh& mesh, const char* tag, double sharpness) {
  if (!std::isfinite(sharpness) || sharpness < 0) {
    throw mesh::InputError(
        mesh.source, std::string("tag '") + tag + "'",
        "sharpness " + std::to_string(sharpness) + " is not a finite value >= 0");
  }
}

void checkVertex(const mesh::Mesh& mesh, const char* tag, uint32_t vertex) {
  if (vertex >= mesh.positions.size()) {
    throw mesh::InputError(mesh.source, std::string("tag '") + tag + "'",
                           "vertex " + std::to_string(vertex) + " is out of range (" +
                               std::to_string(mesh.positions.size()) + " vertices)");
  }
}

void validateForScheme(const mesh::Mesh& mesh, Scheme scheme) {
  if (mesh.faceCount() == 0) {
    throw mesh::InputError(mesh.source, "mesh", "has no faces, so it has no limit surface");
  }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (scheme == Scheme::kLoop && mesh.faceSize(f) != 3) {
      throw mesh::InputError(mesh.source, mesh::describeFace(mesh, f),
                             "Loop subdivision needs triangles; this face has " +
                                 std::to_string(mesh.faceSize(f)) + " corners");
    }
    for (uint32_t p : mesh.facePositions(f)) checkVertex(mesh, "face", p);
  }
  for (const mesh::Crease& crease : mesh.tags.creases) {
    checkVertex(mesh, "crease", crease.v0);
    checkVertex(mesh, "crease", crease.v1);
    checkSharpness(mesh, "crease", crease.sharpness);
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    checkVertex(mesh, "corner", corner.vertex);
    checkSharpness(mesh, "corner", corner.sharpness);
  }
  for (uint32_t hole : mesh.tags.holes) {
    if (hole >= mesh.faceCount()) {
      throw mesh::InputError(mesh.source, "tag 'hole'",
                             "face " + std::to_string(hole) + " is out of range (" +
                                 std::to_string(mesh.faceCount()) + " faces)");
    }
  }
}

Sdc::Options::VtxBoundaryInterpolation sdcBoundary(mesh::BoundaryInterpolation boundary) {
  switch (boundary) {
    case mesh::BoundaryInterpolation::kNone:
      return Sdc::Options::VTX_BOUNDARY_NONE;
    case mesh::BoundaryInterpolation::kEdgeOnly:
      return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
    case mesh::BoundaryInterpolation::kEdgeAndCorner:
      return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
  }
  return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
}

}  // namespace

Sdc::Options sdcOptions(const mesh::SubdivisionTags& tags) {
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(sdcBoundary(tags.boundary));
  options.SetCreasingMethod(tags.crease_method == "chaikin" ? Sdc::Options::CREASE_CHAIKIN
                                                            : Sdc::Options::CREASE_UNIFORM);
  // `t smoothtriangles catmark` asks for Catmark weights, which is also the default; the
  // mesh layer keeps only that the tag was present (OpenSubdiv's shapes only use "catmark").
  options.SetTriangleSubdivision(Sdc::Options::TRI_SUB_CATMARK);
  return options;
}

std::unique_ptr<Far::TopologyRefiner> buildTopologyRefiner(const mesh::Mesh& mesh, Scheme scheme) {
  validateForScheme(mesh, scheme);

  std::vector<int> verts_per_face(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) verts_per_face[f] = int(mesh.faceSize(f));
  const std::vector<Far::Index> face_verts(mesh.corner_positions.begin(),
                                           mesh.corner_positions.end());
  std::vector<Far::Index> crease_pairs;
  std::vector<float> crease_weights;
  for (const mesh::Crease& crease : mesh.tags.creases) {
    crease_pairs.push_back(Far::Index(crease.v0));
    crease_pairs.push_back(Far::Index(crease.v1));
    crease_weights.push_back(float(crease.sharpness));
  }
  std::vector<Far::Index> corner_verts;
  std::vector<float> corner_weights;
  for (const mesh::Corner& corner : mesh.tags.corners) {
    corner_verts.push_back(Far::Index(corner.vertex));
    corner_weights.push_back(float(corner.sharpness));
  }
  const std::vector<Far::Index> holes(mesh.tags.holes.begin(), mesh.tags.holes.end());

  Far::TopologyDescriptor desc;
  desc.numVertices = int(mesh.positions.size());
  desc.numFaces = int(mesh.faceCount());
  desc.numVertsPerFace = verts_per_face.data();
  desc.vertIndicesPerFace = face_verts.data();
  desc.numCreases = int(crease_weights.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = crease_weights.data();
  desc.numCorners = int(corner_weights.size());
  desc.cornerVertexIndices = corner_verts.data();
  desc.cornerWeights = corner_weights.data();
  desc.numHoles = int(holes.size());
  desc.holeIndices = holes.data();

  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  const Factory::Options options(sdcScheme(scheme), sdcOptions(mesh.tags));
  FarErrorCapture capture;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, options));
  if (!refiner) {
    throw mesh::InputError(mesh.source, "mesh topology",
                           "OpenSubdiv cannot build a " + std::string(schemeName(scheme)) +
                               " surface from it: " +
                               (capture.errors().empty() ? "no reason given" : capture.errors()));
  }
  return refiner;
}

}  // namespace tb::osd
