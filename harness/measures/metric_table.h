// A field table: the one place a measure maps its figures struct to declared metrics.
// Each entry names a metric (MetricSpec: name, unit, direction) and where its value comes
// from (a member pointer, or an accessor for derived values); the same table gives the
// measure's declarations and each row's metrics, in the same order. An accessor returning
// std::nullopt leaves the metric out of that row (e.g. a baseline not built above a size).
#pragma once

#include <concepts>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "harness/results/metric_spec.h"
#include "harness/results/results_model.h"

namespace tb::measures {

template <class Figures>
struct MetricField {
  using Accessor = std::function<std::optional<double>(const Figures&)>;

  template <class Member>
  requires std::is_arithmetic_v<Member> MetricField(std::string name, results::Unit unit,
                                                    results::Direction direction,
                                                    Member Figures::*member)
      : spec{std::move(name), unit, direction},
        value([member](const Figures& f) -> std::optional<double> { return double(f.*member); }) {}

  template <class Fn>
  requires(!std::is_member_pointer_v<Fn> && std::invocable<const Fn&, const Figures&>)
      MetricField(std::string name, results::Unit unit, results::Direction direction, Fn accessor)
      : spec{std::move(name), unit, direction}, value(std::move(accessor)) {}

  results::MetricSpec spec;
  Accessor value;
};

template <class Figures>
class MetricTable {
 public:
  MetricTable(std::initializer_list<MetricField<Figures>> fields) : fields_(fields) {}
  // `fields`, then `more` (a measure's optional group, e.g. its compute-path figures).
  MetricTable(std::initializer_list<MetricField<Figures>> fields,
              const std::vector<MetricField<Figures>>& more)
      : fields_(fields) {
    fields_.insert(fields_.end(), more.begin(), more.end());
  }

  std::vector<results::MetricSpec> specs() const {
    std::vector<results::MetricSpec> result;
    for (const MetricField<Figures>& field : fields_) result.push_back(field.spec);
    return result;
  }

  // The row's metrics, in table order, each with its declared unit's spelling.
  std::vector<results::Metric> metrics(const Figures& figures) const {
    std::vector<results::Metric> result;
    for (const MetricField<Figures>& field : fields_) {
      if (const std::optional<double> value = field.value(figures)) {
        result.push_back({field.spec.name, *value, std::string(toString(field.spec.unit))});
      }
    }
    return result;
  }

 private:
  std::vector<MetricField<Figures>> fields_;
};

}  // namespace tb::measures
