// The results database of `tessbench history`: finished run folders (merged shard runs too)
// ingested into one SQLite file, each run keyed by its git sha, commit time, run id, date,
// device and suite, with every record and measure as results.json holds them and the
// samples of timings.json. docs/FORMATS.md, "History database", has the schema.
//
// Writers take the database's write lock for a whole add (BEGIN IMMEDIATE, WAL journal,
// a busy timeout), so two processes adding at once both land, one after the other, and a
// process killed mid-add leaves the database as it was before that add.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "harness/history/sqlite_db.h"
#include "harness/results/compare.h"

namespace tb::history {

// 1: the first layout. 2: runs carry the commit time (RunContext::commit_time), and the
//    `figures` view lists every figure as a row. A version-1 file is read as it is and
//    migrated to 2 by the next `history add`.
inline constexpr int kHistorySchemaVersion = 2;
inline constexpr const char* kDefaultHistoryPath = "results/history.sqlite";

// An open history database and the schema version its file has.
struct HistoryDb {
  std::unique_ptr<Database> db;
  int version = kHistorySchemaVersion;
};

// Opens the history at `path`. Read-only: the file must exist. Writable: a missing file is
// created (its folder too) with the current schema, a version-1 file is migrated. Either
// way a file that is not a tessbench history (not SQLite: its first 16 bytes are not
// "SQLite format 3\0"; empty; damaged; SQLite without tessbench's tables; a newer schema)
// throws HistoryError naming it before anything is written to it.
HistoryDb openHistory(const std::string& path, bool writable);

// One run of the history.
struct RunInfo {
  int64_t id = 0;           // the runs table's key, in the order runs were added
  std::string git_sha;      // as the run's context has it ("<sha>-dirty" for a dirty tree)
  std::string commit_time;  // ISO 8601; empty when the run did not record it
  std::string date;         // when the run was made, ISO 8601 UTC
  std::string run_id;
  std::string device;  // the Vulkan device the run used; "none" without one
  std::string suite;   // "default" or "full"
  std::string folder;  // the run folder as `history add` was given it
  // What orders runs: the commit time, else the run's date.
  const std::string& orderTime() const { return commit_time.empty() ? date : commit_time; }
};

struct AddSummary {
  RunInfo run;
  size_t records = 0;          // records of the run
  size_t measure_results = 0;  // record × measure results
  size_t new_payloads = 0;     // measure results whose figures were not in the database yet
  size_t timings = 0;          // timings.json entries
};

// Ingests the finished run folder `run_dir` in one transaction. Throws HistoryError (or
// std::runtime_error from the results readers, naming the file and field) for a missing or
// unfinished folder, a malformed results.json or timings.json, and a run already in the
// database (same git sha, run id and date).
AddSummary addRun(HistoryDb& history, const std::string& run_dir);

// The concurrency and fault tests' injection point (tests/history/history_add_hooked.cpp):
// called inside every add's transaction once the records are written, before the commit.
// None (nullptr) unless a test program sets one; tessbench never does.
using AddHook = void (*)();
void setAddHook(AddHook hook);

// Every run, in commit order: by orderTime(), then date, then id.
std::vector<RunInfo> listRuns(HistoryDb& history);

// The runs whose git sha starts with `sha_prefix` (at least 4 characters).
std::vector<RunInfo> findRuns(HistoryDb& history, const std::string& sha_prefix);

// A run as compare reads a run folder: results.json's model and timings.json's, rebuilt.
results::RunData loadRun(HistoryDb& history, int64_t run);

// The short sha (7 characters) and the day of orderTime(): "ca87947 2026-11-27".
std::string runLabel(const RunInfo& run);

}  // namespace tb::history
