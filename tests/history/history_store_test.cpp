// The history database (harness/history/history_store.h) on synthetic run folders: what
// goes in comes back (oracle: results.json serialised again, byte for byte), a run is
// refused twice and when unfinished, a file of the previous schema opens, and a file that is
// not a history is refused untouched. SQLite is the real one (Debian's libsqlite3).
#include "harness/history/history_store.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>

#include "tests/cli/cli_support.h"
#include "tests/history/history_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using history::HistoryError;
using testing::SyntheticRun;
using testing::writeSyntheticRun;

TEST(HistoryStore, ARunComesBackAsItWentIn) {
  const fs::path dir = testing::scratchDirectory("history_roundtrip");
  SyntheticRun run;
  run.samples = {0.5, 0.6, 0.7};
  const std::string folder = writeSyntheticRun(dir, run);
  history::HistoryDb db = history::openHistory((dir / "h.sqlite").string(), true);
  const history::AddSummary added = history::addRun(db, folder);
  EXPECT_EQ(added.records, 4u);
  EXPECT_EQ(added.measure_results, 4u);
  EXPECT_EQ(added.timings, 4u);
  EXPECT_EQ(added.run.device, run.device);
  const results::RunData back = history::loadRun(db, added.run.id);
  EXPECT_EQ(results::serializeResults(back.results),
            testing::readFile(fs::path(folder) / "results.json"));
  ASSERT_TRUE(back.timings.has_value());
  EXPECT_EQ(back.timings->measures.at(3).samples, run.samples);
  // Units and directions from the declarations, as SQL rows; every figure through the view.
  history::Statement unit = db.db->prepare(
      "SELECT unit, direction, headline FROM metrics WHERE measure = 'error' AND metric = "
      "'hausdorff'");
  ASSERT_TRUE(unit.step());
  EXPECT_EQ(unit.text(0), "rel_diag");
  EXPECT_EQ(unit.text(1), "lower");
  EXPECT_EQ(unit.integer(2), 1);
  history::Statement figures = db.db->prepare(
      "SELECT count(*), max(value) FROM figures WHERE metric = 'hausdorff' AND technique = 'acc'");
  ASSERT_TRUE(figures.step());
  EXPECT_EQ(figures.integer(0), 4);  // 2 assets × 2 levels
  EXPECT_DOUBLE_EQ(figures.real(1), run.acc_hausdorff);
}

TEST(HistoryStore, RunsAreListedInCommitOrderAndFoundBySha) {
  const fs::path dir = testing::scratchDirectory("history_order");
  history::HistoryDb db = history::openHistory((dir / "h.sqlite").string(), true);
  // Added out of order: the later commit first.
  history::addRun(db, writeSyntheticRun(dir, {"late", "bbbb1111", "2026-02-01T00:00:00+00:00",
                                              "2026-01-01T00:00:00Z"}));
  history::addRun(db, writeSyntheticRun(dir, {"early", "aaaa2222", "2026-01-01T00:00:00+00:00",
                                              "2026-03-01T00:00:00Z"}));
  const std::vector<history::RunInfo> runs = history::listRuns(db);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].run_id, "early");
  EXPECT_EQ(runs[1].run_id, "late");
  EXPECT_EQ(history::findRuns(db, "bbbb").size(), 1u);
  EXPECT_TRUE(history::findRuns(db, "cccc").empty());
  EXPECT_THROW(history::findRuns(db, "bb"), HistoryError);
  EXPECT_EQ(history::runLabel(runs[0]), "aaaa222 2026-01-01");
}

TEST(HistoryStore, ARunAddedTwiceOrUnfinishedIsRefusedAndChangesNothing) {
  const fs::path dir = testing::scratchDirectory("history_refused");
  const std::string path = (dir / "h.sqlite").string();
  history::HistoryDb db = history::openHistory(path, true);
  const std::string folder = writeSyntheticRun(dir, {});
  history::addRun(db, folder);
  try {
    history::addRun(db, folder);
    ADD_FAILURE() << "added twice";
  } catch (const HistoryError& error) {
    EXPECT_NE(std::string(error.what()).find("is already in"), std::string::npos) << error.what();
  }
  SyntheticRun unfinished;
  unfinished.run_id = "u.incomplete";
  EXPECT_THROW(history::addRun(db, writeSyntheticRun(dir, unfinished)), std::runtime_error);
  EXPECT_THROW(history::addRun(db, (dir / "missing").string()), HistoryError);
  fs::create_directories(dir / "empty");
  EXPECT_THROW(history::addRun(db, (dir / "empty").string()), HistoryError);
  EXPECT_EQ(history::listRuns(db).size(), 1u);
}

// Files that are not a history: each refused with HistoryError naming it, byte for byte as
// it was (nor are -wal/-shm files left beside a file that had none).
TEST(HistoryStore, AFileThatIsNotAHistoryIsRefusedUntouched) {
  const fs::path dir = testing::scratchDirectory("history_corrupt");
  std::string sqlite_garbage = std::string("SQLite format 3\0", 16) + std::string(4080, '\x5a');
  const std::vector<std::pair<std::string, std::string>> files = {
      {"text.sqlite", "not a database\n"},
      {"empty.sqlite", ""},
      {"garbage.sqlite", sqlite_garbage},
  };
  for (const auto& [name, contents] : files) {
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary) << contents;
    for (bool writable : {false, true}) {
      try {
        history::openHistory(path.string(), writable);
        ADD_FAILURE() << name << " opened";
      } catch (const HistoryError& error) {
        EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
      }
      EXPECT_EQ(testing::readFile(path), contents) << name;
    }
  }
  // Another program's SQLite database.
  const fs::path other = dir / "other.sqlite";
  {
    history::Database db(other.string(), history::Database::Mode::kCreate);
    db.exec("CREATE TABLE things(x)");
  }
  const std::string before = testing::readFile(other);
  EXPECT_THROW(history::openHistory(other.string(), true), HistoryError);
  EXPECT_EQ(testing::readFile(other), before);
  EXPECT_THROW(history::openHistory((dir / "none.sqlite").string(), false), HistoryError);
}

// Schema 1, as the first tessbench history wrote it: no commit_time column, no figures view.
constexpr const char* kSchemaV1 = R"SQL(
CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE runs(id INTEGER PRIMARY KEY, git_sha TEXT NOT NULL, date TEXT NOT NULL,
  run_id TEXT NOT NULL, device TEXT NOT NULL, suite TEXT NOT NULL, selection TEXT NOT NULL,
  header TEXT NOT NULL, timings TEXT, folder TEXT NOT NULL, UNIQUE(git_sha, run_id, date));
CREATE TABLE metrics(run INTEGER NOT NULL, measure TEXT NOT NULL, metric TEXT NOT NULL,
  unit TEXT NOT NULL, direction TEXT NOT NULL, headline INTEGER NOT NULL,
  PRIMARY KEY(run, measure, metric)) WITHOUT ROWID;
CREATE TABLE records(run INTEGER NOT NULL, ord INTEGER NOT NULL, technique TEXT NOT NULL,
  variant TEXT NOT NULL, asset TEXT NOT NULL, parameters TEXT NOT NULL, warnings TEXT NOT NULL,
  PRIMARY KEY(run, ord)) WITHOUT ROWID;
CREATE TABLE payloads(id INTEGER PRIMARY KEY, hash TEXT NOT NULL UNIQUE, json TEXT NOT NULL);
CREATE TABLE measure_results(run INTEGER NOT NULL, ord INTEGER NOT NULL,
  position INTEGER NOT NULL, measure TEXT NOT NULL, status TEXT NOT NULL,
  payload INTEGER NOT NULL, PRIMARY KEY(run, ord, position)) WITHOUT ROWID;
CREATE TABLE timings(run INTEGER NOT NULL, position INTEGER NOT NULL, technique TEXT NOT NULL,
  variant TEXT NOT NULL, asset TEXT NOT NULL, measure TEXT NOT NULL, seconds REAL NOT NULL,
  samples TEXT NOT NULL, PRIMARY KEY(run, position)) WITHOUT ROWID;
INSERT INTO meta VALUES ('schema_version', '1');
INSERT INTO runs VALUES (1, 'cafe0000', '2025-12-01T00:00:00Z', 'old', 'llvmpipe (test)',
  'default', '{}', '{"schema_version":4,"context":{"date":"2025-12-01T00:00:00Z","run_id":"old",
  "git_sha":"cafe0000","host":"","cpu":"","compiler":"","build_type":"","libraries":{},
  "vulkan_device":"llvmpipe (test)","command_line":""},"assets":[],"skipped":[],"measures":[]}',
  NULL, 'results/old');
INSERT INTO records VALUES (1, 0, 'acc', 'default', 'opensubdiv/catmark_cube', '{}', '[]');
INSERT INTO payloads VALUES (1, 'x:1', '{"measure":"error","status":"ok","reason":"","notes":[],
  "keys":["level"],"metrics":["hausdorff"],"rows":[[["4"],[0.001]]]}');
INSERT INTO measure_results VALUES (1, 0, 0, 'error', 'ok', 1);
)SQL";

TEST(HistoryStore, ADatabaseOfThePreviousSchemaOpensAndIsMigratedByAnAdd) {
  const fs::path dir = testing::scratchDirectory("history_v1");
  const std::string path = (dir / "v1.sqlite").string();
  {
    history::Database db(path, history::Database::Mode::kCreate);
    db.exec(kSchemaV1);
  }
  {
    history::HistoryDb read = history::openHistory(path, false);
    EXPECT_EQ(read.version, 1);
    const std::vector<history::RunInfo> runs = history::listRuns(read);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0].run_id, "old");
    EXPECT_EQ(runs[0].commit_time, "");
    const results::RunData old = history::loadRun(read, runs[0].id);
    EXPECT_EQ(old.results.records.at(0).measures.at(0).rows.at(0).metrics.at(0).value, 0.001);
  }
  history::HistoryDb db = history::openHistory(path, true);
  EXPECT_EQ(db.version, history::kHistorySchemaVersion);
  history::addRun(db, writeSyntheticRun(dir, {}));
  const std::vector<history::RunInfo> runs = history::listRuns(db);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].run_id, "old");  // 2025-12-01, before the new run's commit
  history::Statement version =
      db.db->prepare("SELECT value FROM meta WHERE key = 'schema_version'");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.text(0), std::to_string(history::kHistorySchemaVersion));
}

}  // namespace
}  // namespace tb
