#include "reference/embree_subdivision.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "core/mesh/input_error.h"
#include "reference/embree_device.h"
#include "reference/face_domain.h"
#include "reference/mesh_checks.h"

namespace tb::ref {
namespace {

constexpr uint32_t kMinFaceSize = 3, kMaxFaceSize = 15;  // Embree's subdivision faces

float embreeWeight(double sharpness) {
  return sharpness >= kInfiniteSharpness ? std::numeric_limits<float>::infinity()
                                         : float(sharpness);
}

RTCSubdivisionMode embreeMode(mesh::BoundaryInterpolation boundary) {
  switch (boundary) {
    case mesh::BoundaryInterpolation::kNone:
      return RTC_SUBDIVISION_MODE_NO_BOUNDARY;
    case mesh::BoundaryInterpolation::kEdgeOnly:
      return RTC_SUBDIVISION_MODE_SMOOTH_BOUNDARY;
    case mesh::BoundaryInterpolation::kEdgeAndCorner:
      return RTC_SUBDIVISION_MODE_PIN_CORNERS;
  }
  return RTC_SUBDIVISION_MODE_PIN_CORNERS;
}

void checkRepresentable(const mesh::Mesh& mesh) {
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.faceSize(f) < kMinFaceSize || mesh.faceSize(f) > kMaxFaceSize) {
      throw mesh::InputError(mesh.source, mesh::describeFace(mesh, f),
                             "Embree subdivision faces have 3 to 15 corners; this one has " +
                                 std::to_string(mesh.faceSize(f)));
    }
  }
  checkFinitePositions(mesh.positions, mesh.source);
}

// A new buffer of `count` items, each `components` values of T (e.g. UINT2: 2).
template <class T>
T* newBuffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, size_t count,
             size_t components = 1) {
  return static_cast<T*>(
      rtcSetNewGeometryBuffer(geometry, type, 0, format, components * sizeof(T), count));
}

// Embree takes each unoriented crease edge once; a repeated tag keeps the last
// sharpness, as OpenSubdiv's Far does.
void setCreases(RTCGeometry geometry, const mesh::Mesh& mesh) {
  const auto edges = creaseSharpnessByEdge(mesh);
  if (!edges.empty()) {
    auto* pairs = newBuffer<uint32_t>(geometry, RTC_BUFFER_TYPE_EDGE_CREASE_INDEX, RTC_FORMAT_UINT2,
                                      edges.size(), 2);
    auto* weights = newBuffer<float>(geometry, RTC_BUFFER_TYPE_EDGE_CREASE_WEIGHT, RTC_FORMAT_FLOAT,
                                     edges.size());
    size_t i = 0;
    for (const auto& [edge, sharpness] : edges) {
      pairs[2 * i] = edge.first;
      pairs[2 * i + 1] = edge.second;
      weights[i++] = embreeWeight(sharpness);
    }
  }
  std::map<uint32_t, double> corners;
  for (const mesh::Corner& c : mesh.tags.corners) corners[c.vertex] = c.sharpness;
  if (!corners.empty()) {
    auto* vertices = newBuffer<uint32_t>(geometry, RTC_BUFFER_TYPE_VERTEX_CREASE_INDEX,
                                         RTC_FORMAT_UINT, corners.size());
    auto* weights = newBuffer<float>(geometry, RTC_BUFFER_TYPE_VERTEX_CREASE_WEIGHT,
                                     RTC_FORMAT_FLOAT, corners.size());
    size_t i = 0;
    for (const auto& [vertex, sharpness] : corners) {
      vertices[i] = vertex;
      weights[i++] = embreeWeight(sharpness);
    }
  }
}

}  // namespace

struct EmbreeSubdivision::Impl {
  mesh::Mesh mesh;  // kept for face sizes and error messages
  RTCGeometry geometry = nullptr;
  RTCScene scene = nullptr;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (geometry) rtcReleaseGeometry(geometry);
  }
};

EmbreeSubdivision::EmbreeSubdivision(const mesh::Mesh& mesh) : impl_(std::make_unique<Impl>()) {
  checkRepresentable(mesh);
  impl_->mesh = mesh;
  const RTCDevice device = sharedEmbreeDevice();
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SUBDIVISION);
  impl_->geometry = geometry;
  throwOnEmbreeError(mesh.source, "subdivision geometry");

  // Embree's subdivision kernels load each vertex as 4 floats and assert they are all
  // finite, so the vertices are padded to 16 bytes with a zero.
  auto* vertices = newBuffer<float>(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3,
                                    mesh.positions.size(), 4);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    vertices[4 * i] = float(mesh.positions[i].x);
    vertices[4 * i + 1] = float(mesh.positions[i].y);
    vertices[4 * i + 2] = float(mesh.positions[i].z);
    vertices[4 * i + 3] = 0.0f;
  }
  auto* face_sizes =
      newBuffer<uint32_t>(geometry, RTC_BUFFER_TYPE_FACE, RTC_FORMAT_UINT, mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) face_sizes[f] = mesh.faceSize(f);
  auto* indices = newBuffer<uint32_t>(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT,
                                      mesh.corner_positions.size());
  std::copy(mesh.corner_positions.begin(), mesh.corner_positions.end(), indices);
  setCreases(geometry, mesh);
  if (!mesh.tags.holes.empty()) {
    auto* holes = newBuffer<uint32_t>(geometry, RTC_BUFFER_TYPE_HOLE, RTC_FORMAT_UINT,
                                      mesh.tags.holes.size());
    std::copy(mesh.tags.holes.begin(), mesh.tags.holes.end(), holes);
  }
  rtcSetGeometrySubdivisionMode(geometry, 0, embreeMode(mesh.tags.boundary));
  // The scene is only built so the half-edge topology exists; one segment per edge
  // keeps its ray-tracing tessellation minimal.
  rtcSetGeometryTessellationRate(geometry, 1.0f);
  rtcCommitGeometry(geometry);
  throwOnEmbreeError(mesh.source, "subdivision geometry");

  impl_->scene = rtcNewScene(device);
  rtcAttachGeometry(impl_->scene, geometry);
  rtcCommitScene(impl_->scene);
  throwOnEmbreeError(mesh.source, "subdivision scene");
}

EmbreeSubdivision::~EmbreeSubdivision() = default;
EmbreeSubdivision::EmbreeSubdivision(EmbreeSubdivision&&) noexcept = default;
EmbreeSubdivision& EmbreeSubdivision::operator=(EmbreeSubdivision&&) noexcept = default;

size_t EmbreeSubdivision::faceCount() const { return impl_->mesh.faceCount(); }

LimitPoint EmbreeSubdivision::evaluateNative(size_t face, float u, float v) const {
  checkFaceIndex(impl_->mesh, face);
  float p[3], du[3], dv[3];
  RTCInterpolateArguments args{};
  args.geometry = impl_->geometry;
  args.primID = unsigned(face);
  args.u = u;
  args.v = v;
  args.bufferType = RTC_BUFFER_TYPE_VERTEX;
  args.bufferSlot = 0;
  args.P = p;
  args.dPdu = du;
  args.dPdv = dv;
  args.valueCount = 3;
  rtcInterpolate(&args);
  LimitPoint point;
  point.position = {p[0], p[1], p[2]};
  point.du = {du[0], du[1], du[2]};
  point.dv = {dv[0], dv[1], dv[2]};
  point.normal = normalize(cross(point.du, point.dv));
  return point;
}

LimitPoint EmbreeSubdivision::evaluate(size_t face, double u, double v) const {
  checkFaceIndex(impl_->mesh, face);
  const int size = int(impl_->mesh.faceSize(face));
  const auto& holes = impl_->mesh.tags.holes;
  if (std::find(holes.begin(), holes.end(), uint32_t(face)) != holes.end()) {
    throw mesh::InputError(impl_->mesh.source, mesh::describeFace(impl_->mesh, face),
                           "face is tagged as a hole and has no limit surface");
  }
  checkInsideFaceDomain(impl_->mesh, face, osd::Scheme::kCatmullClark, {u, v});
  const mesh::Vec2d native = faceUvToEmbreeUv(size, {u, v});
  LimitPoint point = evaluateNative(face, float(native.x), float(native.y));
  if (size != 4) {
    point.du = point.du * (1.0 / kSubFaceSpan);
    point.dv = point.dv * (1.0 / kSubFaceSpan);
  }
  return point;
}

}  // namespace tb::ref
