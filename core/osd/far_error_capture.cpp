#include "core/osd/far_error_capture.h"

#include <opensubdiv/far/error.h>

#include <cstdio>
#include <mutex>

namespace tb::osd {
namespace {

namespace Far = OpenSubdiv::Far;

thread_local FarErrorCapture* t_active = nullptr;

void append(std::string* out, const char* message) {
  if (!out->empty()) *out += "; ";
  *out += message ? message : "(no message)";
}

}  // namespace

struct FarErrorSink {
  static void error(Far::ErrorType, const char* message) {
    if (t_active) {
      append(&t_active->errors_, message);
    } else {
      std::fprintf(stderr, "OpenSubdiv error: %s\n", message ? message : "(no message)");
    }
  }
  static void warning(const char* message) {
    if (t_active) {
      append(&t_active->warnings_, message);
    } else {
      std::fprintf(stderr, "OpenSubdiv warning: %s\n", message ? message : "(no message)");
    }
  }
};

FarErrorCapture::FarErrorCapture() : previous_(t_active) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    Far::SetErrorCallback(&FarErrorSink::error);
    Far::SetWarningCallback(&FarErrorSink::warning);
  });
  t_active = this;
}

FarErrorCapture::~FarErrorCapture() { t_active = previous_; }

}  // namespace tb::osd
