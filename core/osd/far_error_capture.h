// Internal: OpenSubdiv Far reports topology errors through one process-wide
// callback that prints to stdout by default. While a FarErrorCapture lives, the
// messages raised on its thread are collected instead, so they can go into an
// InputError; messages from other threads still reach stderr.
#pragma once

#include <string>

namespace tb::osd {

class FarErrorCapture {
 public:
  FarErrorCapture();
  ~FarErrorCapture();
  FarErrorCapture(const FarErrorCapture&) = delete;
  FarErrorCapture& operator=(const FarErrorCapture&) = delete;

  const std::string& errors() const { return errors_; }      // "; "-separated
  const std::string& warnings() const { return warnings_; }  // "; "-separated

 private:
  friend struct FarErrorSink;
  std::string errors_, warnings_;
  FarErrorCapture* previous_;
};

}  // namespace tb::osd
