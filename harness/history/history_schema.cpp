// Opening, creating and migrating a history database (history_store.h).
#include <unistd.h>

#include <cassert>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "harness/history/history_store.h"

namespace tb::history {
namespace {

constexpr std::string_view kSqliteHeader{"SQLite format 3\0", 16};

// Every figure of every run as a row: the measure results' rows (results.json's table
// form) expanded with SQLite's JSON functions. Units and directions: the metrics table.
constexpr const char* kFiguresView = R"SQL(
CREATE VIEW figures AS
SELECT mr.run AS run, r.technique AS technique, r.variant AS variant, r.asset AS asset,
       mr.measure AS measure, line.key AS row_index,
       json_extract(p.json, '$.keys') AS key_names, json_extract(line.value, '$[0]') AS key_values,
       json_extract(p.json, '$.metrics[' || figure.key || ']') AS metric, figure.value AS value
FROM measure_results AS mr
JOIN records AS r ON r.run = mr.run AND r.ord = mr.ord
JOIN payloads AS p ON p.id = mr.payload,
     json_each(p.json, '$.rows') AS line,
     json_each(line.value, '$[1]') AS figure
WHERE figure.type IN ('integer', 'real');
)SQL";

// Schema 2. Units: every time is ISO 8601 text, every `seconds` wall seconds.
constexpr const char* kSchema = R"SQL(
CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
-- One row per run. header: results.json without its records (schema_version, context,
-- assets, skipped, measures), JSON. timings: timings.json without its entries (wall_seconds,
-- threads, repetitions), JSON; NULL when the run folder had no timings.json.
CREATE TABLE runs(
  id INTEGER PRIMARY KEY,
  git_sha TEXT NOT NULL, date TEXT NOT NULL, run_id TEXT NOT NULL,
  device TEXT NOT NULL, suite TEXT NOT NULL, selection TEXT NOT NULL,
  header TEXT NOT NULL, timings TEXT, folder TEXT NOT NULL,
  commit_time TEXT NOT NULL DEFAULT '',
  UNIQUE(git_sha, run_id, date));
-- Each measure's declared metrics: unit ("bytes", "rel_diag", ...), direction
-- ("lower", "higher", "none"), headline: 1-based place in the headline list, 0 when not one.
CREATE TABLE metrics(
  run INTEGER NOT NULL REFERENCES runs(id), measure TEXT NOT NULL, metric TEXT NOT NULL,
  unit TEXT NOT NULL, direction TEXT NOT NULL, headline INTEGER NOT NULL,
  PRIMARY KEY(run, measure, metric)) WITHOUT ROWID;
-- Records in run order (ord from 0); parameters a JSON object, warnings a JSON array.
CREATE TABLE records(
  run INTEGER NOT NULL REFERENCES runs(id), ord INTEGER NOT NULL,
  technique TEXT NOT NULL, variant TEXT NOT NULL, asset TEXT NOT NULL,
  parameters TEXT NOT NULL, warnings TEXT NOT NULL,
  PRIMARY KEY(run, ord)) WITHOUT ROWID;
-- A measure result as results.json's records[].measures[] holds it (status, reason, notes,
-- rows), stored once however many runs have it byte for byte. hash: FNV-1a 64 of the JSON,
-- hex, then ':' and its length in bytes.
CREATE TABLE payloads(id INTEGER PRIMARY KEY, hash TEXT NOT NULL UNIQUE, json TEXT NOT NULL);
CREATE TABLE measure_results(
  run INTEGER NOT NULL REFERENCES runs(id), ord INTEGER NOT NULL, position INTEGER NOT NULL,
  measure TEXT NOT NULL, status TEXT NOT NULL, payload INTEGER NOT NULL REFERENCES payloads(id),
  PRIMARY KEY(run, ord, position)) WITHOUT ROWID;
-- timings.json's entries: seconds = the first sample, samples = every one (JSON array), s.
CREATE TABLE timings(
  run INTEGER NOT NULL REFERENCES runs(id), position INTEGER NOT NULL,
  technique TEXT NOT NULL, variant TEXT NOT NULL, asset TEXT NOT NULL, measure TEXT NOT NULL,
  seconds REAL NOT NULL, samples TEXT NOT NULL,
  PRIMARY KEY(run, position)) WITHOUT ROWID;
)SQL";

// The first 16 bytes of `path`; what is there when the file is shorter.
std::string fileHeader(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string header(16, '\0');
  file.read(header.data(), 16);
  header.resize(size_t(file.gcount()));
  return header;
}

// The schema version the file's meta table records; throws naming the file when the file
// is not a tessbench history. Reads only.
int readVersion(Database& db) {
  Statement tables = db.prepare(
      "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name IN ('meta', 'runs')");
  if (!tables.step() || tables.integer(0) != 2) {
    throw HistoryError(db.path() +
                       ": a SQLite database, but not a tessbench history (no meta "
                       "and runs tables)");
  }
  Statement version = db.prepare("SELECT value FROM meta WHERE key = 'schema_version'");
  if (!version.step()) throw HistoryError(db.path() + ": meta has no schema_version");
  const std::string text = version.text(0);
  const int value = std::atoi(text.c_str());
  if (value < 1 || value > kHistorySchemaVersion) {
    throw HistoryError(db.path() + ": history schema version '" + text +
                       "'; this tessbench reads 1 to " + std::to_string(kHistorySchemaVersion));
  }
  return value;
}

void migrate(HistoryDb& history) {
  if (history.version == kHistorySchemaVersion) return;
  Database& db = *history.db;
  db.exec("BEGIN IMMEDIATE");
  try {
    if (readVersion(db) == 1) {  // another process may have migrated it meanwhile
      db.exec("ALTER TABLE runs ADD COLUMN commit_time TEXT NOT NULL DEFAULT ''");
      db.exec(kFiguresView);
      db.exec("UPDATE meta SET value = '2' WHERE key = 'schema_version'");
    }
    db.exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  history.version = kHistorySchemaVersion;
}

// A new database at `path`, whole or not at all: made under a temporary name beside it and
// linked into place, so a concurrent opener never sees a half-made file; when another
// process linked its own first, that one stays.
void createAtomically(const std::string& path) {
  namespace fs = std::filesystem;
  if (const fs::path parent = fs::path(path).parent_path(); !parent.empty()) {
    std::error_code error;
    fs::create_directories(parent, error);
  }
  const std::string temporary = path + ".creating-" + std::to_string(::getpid());
  try {
    Database db(temporary, Database::Mode::kCreate);
    db.exec("PRAGMA journal_mode = WAL");
    db.exec("BEGIN IMMEDIATE");
    db.exec(kSchema);
    db.exec(kFiguresView);
    db.exec("INSERT INTO meta(key, value) VALUES ('schema_version', '" +
            std::to_string(kHistorySchemaVersion) + "'), ('created_by', 'tessbench history')");
    db.exec("COMMIT");
  } catch (...) {
    ::unlink(temporary.c_str());
    throw;
  }
  const bool linked = ::link(temporary.c_str(), path.c_str()) == 0;
  const int link_error = errno;
  ::unlink(temporary.c_str());
  if (!linked && link_error != EEXIST) {
    throw HistoryError(path + ": cannot create the history database: " + std::strerror(link_error));
  }
}

}  // namespace

HistoryDb openHistory(const std::string& path, bool writable) {
  assert(!path.empty());
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::exists(path, error)) {
    if (!writable) throw HistoryError(path + ": no such history database");
    createAtomically(path);
  }
  if (fs::is_directory(path)) throw HistoryError(path + ": a folder, not a history database");
  const std::string header = fileHeader(path);
  if (header.empty()) throw HistoryError(path + ": an empty file, not a history database");
  if (header != kSqliteHeader) {
    throw HistoryError(path + ": not a SQLite database (no \"SQLite format 3\" header)");
  }
  // Read-only first: a damaged file or another program's database is refused untouched.
  HistoryDb history;
  history.db = std::make_unique<Database>(path, Database::Mode::kReadOnly);
  history.version = readVersion(*history.db);
  if (writable) {
    history.db = std::make_unique<Database>(path, Database::Mode::kReadWrite);
    history.db->exec("PRAGMA journal_mode = WAL");
    history.db->exec("PRAGMA synchronous = NORMAL");
    migrate(history);
  }
  return history;
}

}  // namespace tb::history
