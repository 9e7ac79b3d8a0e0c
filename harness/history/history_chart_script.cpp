#include "harness/history/history_render.h"

namespace tb::history {

// Draws every chart of #chart-data: x is the run's place in commit order (labelled by short
// sha and date), one dataset per series; a step's point is a larger red-edged triangle.
// Hover: the run id, sha, date and figure; click: the same in #point-details. Each canvas
// gets data-rendered="true" once drawn and data-series = its number of lines.
const char* const kHistoryChartScript = R"JS(
(function () {
  'use strict';
  var palette = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f',
                 '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#bab0ac'];
  var data = JSON.parse(document.getElementById('chart-data').textContent);
  var details = document.getElementById('point-details');
  var rendered = {
    id: 'tbRendered',
    afterRender: function (chart) {
      chart.canvas.setAttribute('data-rendered', 'true');
      chart.canvas.setAttribute('data-series', String(chart.data.datasets.length));
    }
  };
  function number(v) {
    if (v === null || v === undefined) return '';
    var rounded = +v.toPrecision(4);
    var tiny = rounded !== 0 && Math.abs(rounded) < 1e-3;
    return Math.abs(rounded) >= 1e5 || tiny ? rounded.toExponential() : String(rounded);
  }
  function describe(chart, series, point) {
    var run = chart.runs[point.x];
    var text = series + ': ' + number(point.y) + ' ' + chart.unit + ' | run ' + run.run_id +
               ' (' + run.sha + ', ' + run.date + ')';
    return point.step ? text + ' | step: ' + point.step : text;
  }
  data.charts.forEach(function (c) {
    var canvas = document.getElementById(c.canvas);
    if (!canvas) return;
    var datasets = c.series.map(function (s) {
      var colour = palette[s.colour % palette.length];
      return {
        label: s.name, data: s.points, borderColor: colour, backgroundColor: colour,
        borderWidth: 1.5, tension: 0,
        pointRadius: s.points.map(function (p) { return p.step ? 8 : 3; }),
        pointStyle: s.points.map(function (p) { return p.step ? 'triangle' : 'circle'; }),
        pointBorderColor: s.points.map(function (p) { return p.step ? '#c00000' : colour; }),
        pointBorderWidth: s.points.map(function (p) { return p.step ? 2 : 1; })
      };
    });
    new Chart(canvas, {
      type: 'line',
      data: { datasets: datasets },
      plugins: [rendered],
      options: {
        animation: false, responsive: true, maintainAspectRatio: false,
        interaction: { mode: 'nearest', intersect: true },
        scales: {
          x: { type: 'linear', min: -0.5, max: c.labels.length - 0.5,
               title: { display: true, text: 'commit (short sha, date)' },
               ticks: { stepSize: 1, includeBounds: false, autoSkip: true,
                        callback: function (v) {
                          return Number.isInteger(v) && c.labels[v] !== undefined ? c.labels[v] : '';
                        } } },
          y: { type: 'linear', title: { display: true, text: c.y_label },
               ticks: { callback: function (v) { return number(v); } } }
        },
        plugins: {
          title: { display: true, text: c.title },
          legend: { position: 'bottom' },
          tooltip: { callbacks: { label: function (ctx) {
            return describe(c, ctx.dataset.label, ctx.raw);
          } } }
        },
        onClick: function (event, elements, chart) {
          if (!elements.length || !details) return;
          var e = elements[0];
          var set = chart.data.datasets[e.datasetIndex];
          details.textContent = c.title + ': ' + describe(c, set.label, set.data[e.index]);
        }
      }
    });
  });
})();
)JS";

}  // namespace tb::history
