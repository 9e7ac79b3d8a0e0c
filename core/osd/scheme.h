// The subdivision scheme a reference surface follows.
#pragma once

#include <string_view>

namespace tb::osd {

enum class Scheme {
  kCatmullClark,  // quads are the regular faces; any N-gon is allowed (N >= 3)
  kLoop,          // triangles only
};

// "catmull-clark" or "loop", for messages and reports.
std::string_view schemeName(Scheme scheme);

// OpenSubdiv's regression shapes carry their scheme in the file name: `loop_*` is
// Loop, everything else (`catmark_*`, user meshes) Catmull-Clark. Only the file
// name counts, not its folder.
Scheme schemeFromShapeName(std::string_view path);

}  // namespace tb::osd
