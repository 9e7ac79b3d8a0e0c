// A run's output folder. Runs are never overwritten, and a run that did not finish never
// leaves a folder that looks finished: the run writes into `<folder>.incomplete/` (with a
// marker file and a journal of the records measured so far) and renames it to `<folder>`
// only once results.json and the report are complete. A run killed at any point leaves at
// most the `.incomplete` folder, which `report` and `merge` refuse.
#pragma once

#include <string>
#include <vector>

namespace tb::results {

// The marker file of an unfinished run folder and the journal beside it: one JSON line per
// record, appended as each record is measured.
inline constexpr const char* kIncompleteMarker = "INCOMPLETE";
inline constexpr const char* kRecordJournal = "records.jsonl";
inline constexpr const char* kIncompleteSuffix = ".incomplete";

// The folder a run writes into until it finishes.
class PendingRunFolder {
 public:
  // A run folder `<root>/<run_id>`. When run_id is empty one is made from the UTC time
  // (YYYYMMDD-HHMMSS), with a suffix -2, -3, ... if that name is taken (finished or not).
  // An explicit run_id that is taken is an error. Creates `root` when missing. Throws
  // std::runtime_error with one line naming the folder when it cannot be created (a
  // read-only or missing parent, a path through a regular file, no space): this is checked
  // before any measuring, so an unwritable --out fails at once.
  static PendingRunFolder forRun(const std::string& root, const std::string& run_id);
  // The run folder `final_path` itself (`merge --out`), with any missing parents. A folder
  // that exists is an error.
  static PendingRunFolder at(const std::string& final_path);

  PendingRunFolder(PendingRunFolder&& other) noexcept;
  PendingRunFolder& operator=(PendingRunFolder&&) = delete;
  // Unless finish() ran: removes the pending folder, and the parents this object created
  // while they are empty, so a run that failed (bad input, an error) leaves nothing behind.
  ~PendingRunFolder();

  const std::string& runId() const { return run_id_; }          // the final folder's name
  const std::string& finalPath() const { return final_path_; }  // where finish() puts it
  const std::string& pendingPath() const { return pending_path_; }

  // Appends one line (a record's JSON, no newline inside) to the journal. Callers
  // serialise calls. Throws naming the journal when the write fails (e.g. no space).
  void journal(const std::string& line);
  // Writes `<pending>/<name>`, which must not exist yet; folders in `name` ("tables/x.csv")
  // are made.
  void writeFile(const std::string& name, const std::string& contents);
  // Removes the journal and the marker and renames the folder to finalPath(), refusing to
  // replace a folder that appeared there meanwhile. Returns finalPath().
  std::string finish();

 private:
  PendingRunFolder() = default;
  // What the destructor does; after it the object owns nothing.
  void abandon() noexcept;
  std::string run_id_, final_path_, pending_path_;
  std::vector<std::string> created_folders_;  // the parents this object made, deepest first
  int journal_fd_ = -1;
  bool finished_ = false;
};

// Throws std::runtime_error with one line when `folder` is an unfinished run folder (its
// marker is there, or its name ends in .incomplete): a run that was killed or failed before
// it completed. Used by `report` and `merge`, which read only finished runs.
void requireFinishedRunFolder(const std::string& folder);

// Writes a file that must not exist yet (O_EXCL); throws naming the path.
void writeNewFile(const std::string& path, const std::string& contents);

std::string utcTimestampIso8601();

}  // namespace tb::results
