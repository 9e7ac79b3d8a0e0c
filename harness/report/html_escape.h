// Escaping for what report.html places in its markup and scripts, so that no text of a run
// (a technique name, a note, a file of the pictures) can end a tag or a script early.
#pragma once

#include <string>
#include <string_view>

namespace tb::report {

// Text and attribute values: & < > " ' as character references.
std::string escapeHtml(std::string_view text);

// JSON text (nlohmann's dump) placed inside <script type="application/json">: '<', '>'
// and '&' become \u003c, \u003e, \u0026. They occur only inside JSON strings, where the
// escapes mean the same characters, so JSON.parse reads the same value and the element's
// text never holds "</script" or "<!--".
std::string jsonForScript(std::string_view json);

// JavaScript source (Chart.js) placed inside <script>: "</script" becomes "<\/script" and
// "<!--" becomes "<\!--" (any case), which inside a JS string or regular expression mean
// the same characters; outside one they do not occur in working code.
std::string javascriptForScript(std::string_view source);

}  // namespace tb::report
