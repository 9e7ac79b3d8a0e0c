#include <algorithm>
#include <cassert>

#include "harness/results/compare.h"

namespace tb::results {
namespace {

bool selects(const std::vector<std::string>& wanted, const std::string& value) {
  return wanted.empty() || std::find(wanted.begin(), wanted.end(), value) != wanted.end();
}

// An asset by its full name or its last path component ("loop_cube").
bool selectsAsset(const std::vector<std::string>& wanted, const std::string& asset) {
  if (wanted.empty()) return true;
  const std::string short_name = asset.substr(asset.rfind('/') + 1);
  return std::any_of(wanted.begin(), wanted.end(),
                     [&](const std::string& w) { return w == asset || w == short_name; });
}

}  // namespace

void filterRun(const RunFilter& filter, RunData* run) {
  assert(run != nullptr);
  if (filter.empty()) return;
  std::vector<Record>& records = run->results.records;
  std::erase_if(records, [&](const Record& record) {
    return !selects(filter.techniques, record.technique) ||
           !selectsAsset(filter.assets, record.asset);
  });
  for (Record& record : records) {
    std::erase_if(record.measures,
                  [&](const MeasureResult& m) { return !selects(filter.measures, m.measure); });
  }
  if (run->timings) {
    std::erase_if(run->timings->measures, [&](const TimingEntry& entry) {
      return !selects(filter.techniques, entry.technique) ||
             !selectsAsset(filter.assets, entry.asset) || !selects(filter.measures, entry.measure);
    });
  }
}

std::vector<std::string> unmatchedFilterValues(const RunFilter& filter,
                                               const std::vector<const RunData*>& runs) {
  std::vector<std::string> unmatched;
  auto anyRecord = [&](auto&& matches) {
    return std::any_of(runs.begin(), runs.end(), [&](const RunData* run) {
      return std::any_of(run->results.records.begin(), run->results.records.end(), matches);
    });
  };
  for (const std::string& t : filter.techniques) {
    if (!anyRecord([&](const Record& r) { return r.technique == t; }))
      unmatched.push_back("--technique " + t);
  }
  for (const std::string& a : filter.assets) {
    if (!anyRecord([&](const Record& r) { return selectsAsset({a}, r.asset); }))
      unmatched.push_back("--asset " + a);
  }
  for (const std::string& m : filter.measures) {
    if (!anyRecord([&](const Record& r) {
          return std::any_of(r.measures.begin(), r.measures.end(),
                             [&](const MeasureResult& x) { return x.measure == m; });
        }))
      unmatched.push_back("--measure " + m);
  }
  return unmatched;
}

}  // namespace tb::results
