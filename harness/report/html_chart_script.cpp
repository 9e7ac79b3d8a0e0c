#include "harness/report/html_chart_script.h"

namespace tb::report {

const char* const kHtmlErrorScript = R"JS(
(function () {
  'use strict';
  function report(text) {
    var list = document.getElementById('script-errors');
    if (!list) return;
    var item = document.createElement('li');
    item.textContent = text;
    list.appendChild(item);
    list.hidden = false;
  }
  window.tbReportError = report;
  window.addEventListener('error', function (event) {
    var where = event.filename ? ' (' + event.filename + ':' + event.lineno + ')' : '';
    report((event.message || 'script error') + where);
  });
  window.addEventListener('unhandledrejection', function (event) {
    report('unhandled promise rejection: ' + event.reason);
  });
})();
)JS";

const char* const kHtmlChartScript = R"JS(
(function () {
  'use strict';
  // Tableau 10: distinct hues that stay apart in print and for most colour-blind readers.
  var palette = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f',
                 '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#bab0ac'];
  var data = JSON.parse(document.getElementById('chart-data').textContent);
  var rendered = {
    id: 'tbRendered',
    afterRender: function (chart) { chart.canvas.setAttribute('data-rendered', 'true'); }
  };
  function number(v) {
    if (v === null || v === undefined) return '';
    var rounded = +v.toPrecision(4);  // 4 significant digits, trailing zeros dropped
    var tiny = rounded !== 0 && Math.abs(rounded) < 1e-3;
    return Math.abs(rounded) >= 1e5 || tiny ? rounded.toExponential() : String(rounded);
  }
  // Log axes label 1, 2 and 5 of each decade (only 1 over more than 4 decades), written
  // short; Chart.js's own labels print every digit of 1e-13.
  function logTick(value) {
    if (!(value > 0)) return '';
    var mantissa = Math.round(value / Math.pow(10, Math.floor(Math.log10(value) + 1e-9)));
    var wide = this.max / this.min > 1e4;
    return mantissa === 1 || (!wide && (mantissa === 2 || mantissa === 5)) ? number(value) : '';
  }
  function axis(type, title) {
    var scale = { type: type, title: { display: true, text: title } };
    if (type === 'logarithmic') scale.ticks = { callback: logTick };
    if (type === 'linear') scale.ticks = { callback: function (value) { return number(value); } };
    return scale;
  }
  function pointDatasets(chart) {
    var sets = chart.series.map(function (s) {
      var colour = palette[s.colour % palette.length];
      return {
        label: s.name,
        data: s.points,
        showLine: chart.kind === 'line',
        borderColor: colour,
        backgroundColor: colour,
        pointRadius: s.points.map(function (p) { return p.recommended ? 11 : p.front ? 6 : 3; }),
        pointStyle: s.points.map(function (p) { return p.recommended ? 'star' : 'circle'; }),
        pointBorderWidth: s.points.map(function (p) { return p.recommended ? 3 : 1; }),
        pointBorderColor: s.points.map(function (p) { return p.front ? '#000' : colour; })
      };
    });
    if (chart.pareto) {
      var front = [];
      chart.series.forEach(function (s) {
        s.points.forEach(function (p) { if (p.front) front.push(p); });
      });
      front.sort(function (a, b) { return a.x - b.x; });
      sets.push({ label: 'Pareto front', data: front, showLine: true, borderColor: '#333',
                  backgroundColor: '#333', borderDash: [5, 4], pointRadius: 0 });
    }
    return sets;
  }
  function barDatasets(chart) {
    return chart.series.map(function (s) {
      var values = chart.categories.map(function () { return null; });
      s.points.forEach(function (p) { values[p.x] = p.y; });
      return { label: s.name, data: values, backgroundColor: palette[s.colour % palette.length] };
    });
  }
  function config(chart) {
    var bar = chart.kind === 'bar';
    var x = bar ? axis('category', chart.x_label)
                : axis(chart.log_x ? 'logarithmic' : 'linear', chart.x_label);
    var y = axis(chart.log_y ? 'logarithmic' : 'linear', chart.y_label);
    return {
      type: bar ? 'bar' : 'scatter',
      data: bar ? { labels: chart.categories, datasets: barDatasets(chart) }
                : { datasets: pointDatasets(chart) },
      options: {
        animation: false,
        responsive: true,
        maintainAspectRatio: false,
        scales: { x: x, y: y },
        plugins: {
          title: { display: chart.title !== '', text: chart.title },
          legend: { labels: { boxWidth: 10, font: { size: 10 } } },
          tooltip: {
            callbacks: {
              label: function (context) {
                var p = context.raw;
                if (bar) return context.dataset.label + ': ' + number(p);
                var what = p.label ? ' ' + p.label : '';
                return context.dataset.label + what + ': (' + number(p.x) + ', ' + number(p.y) + ')';
              }
            }
          }
        }
      },
      plugins: [rendered]
    };
  }
  data.charts.forEach(function (chart) {
    var canvas = document.getElementById(chart.canvas);
    try {
      new Chart(canvas.getContext('2d'), config(chart));
    } catch (error) {
      window.tbReportError(chart.canvas + ': ' + error.message);
    }
  });
})();
)JS";

}  // namespace tb::report
