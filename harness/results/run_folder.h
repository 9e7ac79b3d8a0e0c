// A run's output folder. Runs are never overwritten: each gets a new folder.
#pragma once

#include <string>

namespace tb {

// Creates `<root>/<run_id>` and returns its path. When run_id is empty, one is
// made from the UTC time (YYYYMMDD-HHMMSS) and, if that folder exists, a suffix
// -2, -3, ... is added. An explicit run_id that already exists is an error
// (std::runtime_error naming the folder): an earlier result is never replaced.
std::string createRunFolder(const std::string& root, const std::string& run_id,
                            std::string* chosen_run_id);

// Creates the run folder `path` itself (and any missing parents) for `tessbench merge
// --out`. A folder that already exists is an error (std::runtime_error naming it).
void createNewRunFolder(const std::string& path);

// Writes a file that must not exist yet (O_EXCL); throws naming the path.
void writeNewFile(const std::string& path, const std::string& contents);

std::string utcTimestampIso8601();

}  // namespace tb
