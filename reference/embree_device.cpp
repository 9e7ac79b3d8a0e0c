#include "reference/embree_device.h"

#include <algorithm>

#include "core/mesh/input_error.h"

namespace tb::ref {
namespace {

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_UNKNOWN:
      return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
  }
  return "unrecognised error code";
}

}  // namespace

RTCDevice sharedEmbreeDevice() {
  static const RTCDevice device = [] {
    RTCDevice created = rtcNewDevice("verbose=0");
    if (!created) {
      throw mesh::InputError(
          "embree", "device",
          std::string("rtcNewDevice failed: ") + errorName(rtcGetDeviceError(nullptr)));
    }
    return created;
  }();
  return device;
}

void throwOnEmbreeError(const std::string& source, const std::string& element) {
  const RTCError code = rtcGetDeviceError(sharedEmbreeDevice());
  if (code != RTC_ERROR_NONE) {
    throw mesh::InputError(source, element, std::string("Embree failed: ") + errorName(code));
  }
}

void attachTriangleGeometry(RTCScene scene, std::span<const mesh::Vec3d> positions,
                            std::span<const std::array<uint32_t, 3>> triangles,
                            bool share_triangles) {
  if (triangles.empty()) return;
  RTCGeometry geometry = rtcNewGeometry(sharedEmbreeDevice(), RTC_GEOMETRY_TYPE_TRIANGLE);
  // Padded to 16 bytes with a zero: Embree loads vertices as 4 floats.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), positions.size()));
  for (size_t i = 0; i < positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[4 * i + size_t(k)] = float(positions[i][k]);
    vertices[4 * i + 3] = 0.0f;
  }
  static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t));
  if (share_triangles) {
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               triangles.data(), 0, 3 * sizeof(uint32_t), triangles.size());
  } else {
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), triangles.size()));
    for (size_t t = 0; t < triangles.size(); ++t) {
      std::copy(triangles[t].begin(), triangles[t].end(), indices + 3 * t);
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);  // the scene holds it
}

}  // namespace tb::ref
