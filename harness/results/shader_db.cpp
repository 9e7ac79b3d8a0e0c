#include "harness/results/shader_db.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <utility>

namespace tb::results {
namespace {

// A program's figures, by metric name.
using Figures = std::map<std::string, double>;
// group value -> program name -> figures, with the programs in first-seen order.
struct Programs {
  std::vector<std::string> groups;
  std::map<std::string, std::vector<std::string>> order;
  std::map<std::string, std::map<std::string, Figures>> figures;
};

std::string programName(const Record& record, const MetricRow& row, const ShaderDbSpec& spec) {
  std::string name = record.technique + "/" + record.variant + " " + record.asset;
  for (const auto& [key, value] : row.keys) {
    if (key == spec.group_key) continue;
    if (std::find(spec.ignore_keys.begin(), spec.ignore_keys.end(), key) != spec.ignore_keys.end())
      continue;
    name += " " + key + "=" + value;
  }
  return name;
}

Programs programsOf(const Results& results, const std::string& measure, const ShaderDbSpec& spec) {
  Programs programs;
  for (const Record& record : results.records) {
    for (const MeasureResult& result : record.measures) {
      if (result.measure != measure) continue;
      for (const MetricRow& row : result.rows) {
        const auto group = row.keys.find(spec.group_key);
        if (row.status != MeasureStatus::kOk || group == row.keys.end()) continue;
        if (!programs.order.count(group->second)) programs.groups.push_back(group->second);
        const std::string name = programName(record, row, spec);
        std::map<std::string, Figures>& in_group = programs.figures[group->second];
        if (!in_group.count(name)) programs.order[group->second].push_back(name);
        for (const Metric& m : row.metrics) in_group[name][m.name] = m.value;
      }
    }
  }
  return programs;
}

// Worse by the direction: higher for lower-is-better (and for context figures).
bool worse(Direction direction, double base, double current) {
  return direction == Direction::kHigherIsBetter ? current < base : current > base;
}

ShaderDbMetric summarise(const std::string& metric, Direction direction,
                         const std::vector<std::string>& names,
                         const std::map<std::string, Figures>& base,
                         const std::map<std::string, Figures>& current, size_t* shared) {
  ShaderDbMetric out{.metric = metric, .direction = direction};
  size_t count = 0;
  for (const std::string& name : names) {
    const auto b = base.find(name);
    if (b == base.end()) continue;
    const auto bm = b->second.find(metric);
    const auto cm = current.at(name).find(metric);
    if (bm == b->second.end() || cm == current.at(name).end()) continue;
    ++count;
    out.total_base += bm->second;
    out.total_current += cm->second;
    if (bm->second == cm->second) continue;
    ++out.affected;
    out.affected_base += bm->second;
    out.affected_current += cm->second;
    if (worse(direction, bm->second, cm->second)) {
      ++out.hurt;
      out.worst_hurt.push_back({name, bm->second, cm->second});
    } else {
      ++out.helped;
    }
  }
  *shared = std::max(*shared, count);
  auto relative = [](const ShaderDbMetric::Program& p) {
    return std::abs(p.current - p.base) / std::max(std::abs(p.base), 1.0);
  };
  std::stable_sort(out.worst_hurt.begin(), out.worst_hurt.end(),
                   [&](const auto& a, const auto& b) { return relative(a) > relative(b); });
  if (out.worst_hurt.size() > 5) out.worst_hurt.resize(5);
  return out;
}

std::string percent(double base, double current) {
  if (base == current) return "0.00%";
  if (base == 0) return "inf%";
  return fmt::format("{:+.2f}%", 100.0 * (current - base) / std::abs(base));
}

std::string figure(double value) {
  return value == std::floor(value) && std::abs(value) < 1e15 ? fmt::format("{:.0f}", value)
                                                              : fmt::format("{:.6g}", value);
}

// The programs of both runs in which any of the spec's metrics differs.
size_t changedPrograms(const ShaderDbSpec& spec, const std::map<std::string, Figures>& base,
                       const std::map<std::string, Figures>& current) {
  size_t changed = 0;
  for (const auto& [name, figures] : current) {
    const auto b = base.find(name);
    if (b == base.end()) continue;
    for (const std::string& metric : spec.metrics) {
      const auto x = b->second.find(metric), y = figures.find(metric);
      if (x != b->second.end() && y != figures.end() && x->second != y->second) {
        ++changed;
        break;
      }
    }
  }
  return changed;
}

}  // namespace

std::vector<ShaderDbSummary> shaderDbSummaries(const Results& base, const Results& current) {
  std::vector<ShaderDbSummary> summaries;
  for (const MeasureDeclaration& declaration : current.measures) {
    const ShaderDbSpec& spec = declaration.shader_db;
    if (spec.group_key.empty()) continue;
    const Programs before = programsOf(base, declaration.measure, spec);
    const Programs after = programsOf(current, declaration.measure, spec);
    for (const std::string& group : after.groups) {
      if (!before.figures.count(group)) continue;
      ShaderDbSummary summary{declaration.measure, group, 0, 0, {}};
      for (const std::string& metric : spec.metrics) {
        const MetricSpec* declared = declaration.find(metric);
        assert(declared != nullptr && "a shader-db metric is declared by its measure");
        const Direction direction = declared ? declared->direction : Direction::kLowerIsBetter;
        summary.metrics.push_back(summarise(metric, direction, after.order.at(group),
                                            before.figures.at(group), after.figures.at(group),
                                            &summary.shared_programs));
      }
      summary.affected_programs =
          changedPrograms(spec, before.figures.at(group), after.figures.at(group));
      summaries.push_back(std::move(summary));
    }
  }
  return summaries;
}

std::string renderShaderDb(const std::vector<ShaderDbSummary>& summaries) {
  std::string out;
  for (const ShaderDbSummary& s : summaries) {
    out += fmt::format("### {} on {}: {} shared programs, {} affected programs\n\n```\n", s.measure,
                       s.group, s.shared_programs, s.affected_programs);
    for (const ShaderDbMetric& m : s.metrics) {
      out += fmt::format("total {} in shared programs: {} -> {} ({})\n", m.metric,
                         figure(m.total_base), figure(m.total_current),
                         percent(m.total_base, m.total_current));
      out +=
          fmt::format("{} in affected programs: {} -> {} ({})\n", m.metric, figure(m.affected_base),
                      figure(m.affected_current), percent(m.affected_base, m.affected_current));
      out += fmt::format("helped: {}\nHURT: {}\n", m.helped, m.hurt);
      for (const ShaderDbMetric::Program& p : m.worst_hurt) {
        out += fmt::format("  HURT {}: {} -> {} ({})\n", p.name, figure(p.base), figure(p.current),
                           percent(p.base, p.current));
      }
      out += "\n";
    }
    out += "```\n\n";
  }
  return out;
}

nlohmann::ordered_json shaderDbToJson(const std::vector<ShaderDbSummary>& summaries) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ShaderDbSummary& s : summaries) {
    nlohmann::ordered_json metrics = nlohmann::ordered_json::array();
    for (const ShaderDbMetric& m : s.metrics) {
      nlohmann::ordered_json worst = nlohmann::ordered_json::array();
      for (const ShaderDbMetric::Program& p : m.worst_hurt) {
        worst.push_back({{"program", p.name}, {"base", p.base}, {"new", p.current}});
      }
      metrics.push_back({{"metric", m.metric},
                         {"total", {m.total_base, m.total_current}},
                         {"affected_programs", m.affected},
                         {"affected", {m.affected_base, m.affected_current}},
                         {"helped", m.helped},
                         {"hurt", m.hurt},
                         {"worst_hurt", worst}});
    }
    out.push_back({{"measure", s.measure},
                   {"group", s.group},
                   {"shared_programs", s.shared_programs},
                   {"affected_programs", s.affected_programs},
                   {"metrics", metrics}});
  }
  return out;
}

}  // namespace tb::results
