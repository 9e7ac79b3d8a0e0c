#include "core/osd/scheme.h"

namespace tb::osd {

std::string_view schemeName(Scheme scheme) {
  return scheme == Scheme::kLoop ? "loop" : "catmull-clark";
}

Scheme schemeFromShapeName(std::string_view path) {
  const size_t slash = path.find_last_of("/\\");
  const std::string_view file = slash == std::string_view::npos ? path : path.substr(slash + 1);
  return file.starts_with("loop_") ? Scheme::kLoop : Scheme::kCatmullClark;
}

}  // namespace tb::osd
