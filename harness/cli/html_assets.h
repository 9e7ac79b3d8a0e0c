// What report.html embeds besides the results: Chart.js (Debian's libjs-chart.js, read from
// a path set at configure time, TB_CHARTJS_PATH, or at run time, TESSBENCH_CHARTJS) and the
// run folder's pictures (pictures/pictures.json and its PNGs, written by `run`).
#pragma once

#include <string>

#include "harness/report/html.h"

namespace tb::cli {

// The Chart.js file report.html inlines: $TESSBENCH_CHARTJS when set, else the configured
// default.
std::string chartJsPath();

// Chart.js and the pictures of `run_dir`. Never throws for what is missing or malformed:
// no Chart.js leaves chartjs_source empty with the reason; no pictures.json, or one in
// another format, leaves no pictures and a note saying why; a picture whose file is
// missing or not a PNG is left out with a note.
report::HtmlAssets loadHtmlAssets(const std::string& run_dir);

// report.html for `run`: without Chart.js, the page says charts are unavailable and one
// warning line goes to stderr.
std::string renderRunHtml(const results::Results& results, const std::string& run_dir);

}  // namespace tb::cli
