#include "reference/embree_device.h"

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
      throw InputError(
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
    throw InputError(source, element, std::string("Embree failed: ") + errorName(code));
  }
}

}  // namespace tb::ref
