#include "harness/report/csv_tables.h"

#include <gtest/gtest.h>

namespace tb {
namespace {

TEST(CsvTables, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(report::csvCell("plain"), "plain");
  EXPECT_EQ(report::csvCell("a,b"), "\"a,b\"");
  EXPECT_EQ(report::csvCell("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(report::csvCell("two\nlines"), "\"two\nlines\"");
}

// Every row of a measure is a line: keys, status, reason, then the declared metrics with
// units in the header; a record whose measure did not run is one line with its status.
TEST(CsvTables, OneFilePerMeasureWithEveryRow) {
  results::Results results;
  results::MeasureDeclaration cracks{"cracks", "Cracks", "d", {}, {"points_not_equal"}, {}};
  cracks.metrics = {{"points_not_equal", results::Unit::kCount, results::Direction::kLowerIsBetter},
                    {"max_gap_world", results::Unit::kWorld, results::Direction::kLowerIsBetter}};
  results.measures.push_back(cracks);
  results::Record record{"acc", "default", "cube", {}, {"a, warning"}, {}};
  results::MeasureResult m{"cracks", results::MeasureStatus::kOk, "", {}, {}};
  m.rows.push_back({{{"backend", "cpu_float"}, {"level", "2"}},
                    {{"max_gap_world", 0.125, "world"}, {"points_not_equal", 3, "count"}}});
  m.rows.push_back(results::unmeasuredRow({{"backend", "gpu"}, {"level", "2"}},
                                          results::MeasureStatus::kSkipped, "no Vulkan device"));
  record.measures.push_back(m);
  results.records.push_back(record);
  results::Record other{"pn", "pn", "cube", {}, {}, {}};
  other.measures.push_back({"cracks", results::MeasureStatus::kFailed, "device lost", {}, {}});
  results.records.push_back(other);

  const auto files = report::renderCsvTables(results);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].first, "tables/cracks.csv");
  EXPECT_EQ(files[0].second,
            "technique,variant,asset,backend,level,status,reason,points_not_equal [count],"
            "max_gap_world [world]\r\n"
            "acc,default,cube,cpu_float,2,ok,,3,0.125\r\n"
            "acc,default,cube,gpu,2,skipped,no Vulkan device,,\r\n"
            "pn,pn,cube,,,failed,device lost,,\r\n");
  EXPECT_EQ(files[1].first, "tables/warnings.csv");
  EXPECT_EQ(files[1].second,
            "technique,variant,asset,warning\r\nacc,default,cube,\"a, warning\"\r\n");
}

}  // namespace
}  // namespace tb
