// report.html: one self-contained page of a run (no network, nothing beside it): the run's
// context, the charts each measure declares (MeasureDeclaration::plots, drawn by Chart.js
// inlined into the page) and the pictures rendered of each surface (PNG as data: URIs).
// Reads only the results model and what the caller hands in; deterministic for the same
// results and assets.
#pragma once

#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

struct HtmlPicture {
  std::string caption;    // "error (0 … 0.0012 rel_diag)"
  std::string png_bytes;  // the PNG file's bytes
};

// The pictures of one technique × asset (error heat map and wireframe).
struct HtmlPictureGroup {
  std::string title;  // "acc/default on opensubdiv/catmark_cube"
  std::string note;   // "uniform level 8; colour: max of the triangle's 3 vertex errors"
  std::vector<HtmlPicture> pictures;
  // Every picture has the same colour scale: its colour bar (the strip below each square
  // render) is shown under the first picture only.
  bool shared_scale = false;
};

// What the page embeds besides the results (read by the CLI: harness/cli/html_assets.h).
struct HtmlAssets {
  // Chart.js's UMD build (defines the global `Chart`); empty: the page says why there are
  // no charts (chartjs_missing_reason).
  std::string chartjs_source;
  std::string chartjs_missing_reason;
  std::vector<HtmlPictureGroup> pictures;
  // Shown in the pictures section: why there are none, or which were left out.
  std::vector<std::string> picture_notes;
  // Where the default variants crack (one group, "Where the default variants crack": a
  // picture per technique × asset whose CPU cracks row has unequal points, the points
  // marked); shown first in the pictures section. Empty when nothing cracks.
  std::vector<HtmlPictureGroup> crack_pictures = {};
};

std::string renderHtml(const results::Results& results, const HtmlAssets& assets);

}  // namespace tb::report
