// The script of report.html, kept apart from the markup that html.cpp writes.
#pragma once

namespace tb::report {

// Installed before any other script: writes every script error (and unhandled promise
// rejection) as a list item into #script-errors, so a browser test reads them from the DOM.
extern const char* const kHtmlErrorScript;

// Draws each chart of the JSON in #chart-data into its <canvas> with Chart.js and sets
// data-rendered="true" on the canvas once Chart.js has drawn it (an afterRender plugin).
extern const char* const kHtmlChartScript;

}  // namespace tb::report
