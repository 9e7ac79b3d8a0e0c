#include "harness/history/history_store.h"

#include <fmt/format.h>

#include <cassert>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/mesh/fnv1a.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "harness/results/timings_json.h"

namespace tb::history {
namespace {

using Json = nlohmann::ordered_json;

// FNV-1a, 64 bits, as hex, then ':' and the length: the payloads' content address.
std::string contentHash(std::string_view bytes) {
  return fmt::format("{:016x}:{}", mesh::fnv1a64(bytes), bytes.size());
}

// A run folder's results.json, checked against the results model (throws naming the file
// and field), and kept as JSON so each measure result is stored as the file has it.
Json readRunDocument(const std::string& run_dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(run_dir)) throw HistoryError(run_dir + ": no such run folder");
  results::requireFinishedRunFolder(run_dir);
  const std::string path = run_dir + "/results.json";
  std::ifstream file(path);
  if (!file) throw HistoryError(path + ": missing: not a finished run folder");
  Json document;
  try {
    document = Json::parse(file);
    results::resultsFromJson(document);
  } catch (const nlohmann::json::parse_error& error) {
    throw HistoryError(path + ": not valid JSON (" + std::string(error.what()) + ")");
  } catch (const std::runtime_error& error) {
    throw HistoryError(path + ": " + error.what());
  }
  return document;
}

// Rolls back unless committed: an add that throws leaves the database as it was.
class Transaction {
 public:
  explicit Transaction(Database& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }
  ~Transaction() {
    if (!committed_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
  }
  void commit() {
    db_.exec("COMMIT");
    committed_ = true;
  }

 private:
  Database& db_;
  bool committed_ = false;
};

AddHook add_hook = nullptr;  // setAddHook's

void insertDeclarations(Database& db, int64_t run, const Json& measures) {
  Statement insert = db.prepare(
      "INSERT INTO metrics(run, measure, metric, unit, direction, headline) VALUES "
      "(?, ?, ?, ?, ?, ?)");
  for (const Json& declaration : measures) {
    const std::vector<std::string> headline =
        declaration.value("headline", std::vector<std::string>{});
    for (const Json& metric : declaration.at("metrics")) {
      const std::string name = metric.at("name").get<std::string>();
      const auto rank = std::find(headline.begin(), headline.end(), name) - headline.begin();
      insert.bind(1, run).bind(2, declaration.at("measure").get<std::string>()).bind(3, name);
      insert.bind(4, metric.at("unit").get<std::string>())
          .bind(5, metric.at("direction").get<std::string>())
          .bind(6, int64_t(size_t(rank) < headline.size() ? rank + 1 : 0));
      insert.run();
    }
  }
}

// Records and their measure results; returns how many payloads were new.
size_t insertRecords(Database& db, int64_t run, const Json& records, AddSummary* summary) {
  Statement record_insert = db.prepare(
      "INSERT INTO records(run, ord, technique, variant, asset, parameters, warnings) VALUES "
      "(?, ?, ?, ?, ?, ?, ?)");
  Statement payload_insert = db.prepare("INSERT OR IGNORE INTO payloads(hash, json) VALUES (?, ?)");
  Statement payload_find = db.prepare("SELECT id FROM payloads WHERE hash = ?");
  Statement result_insert = db.prepare(
      "INSERT INTO measure_results(run, ord, position, measure, status, payload) VALUES "
      "(?, ?, ?, ?, ?, ?)");
  size_t new_payloads = 0;
  for (size_t ord = 0; ord < records.size(); ++ord) {
    const Json& record = records[ord];
    record_insert.bind(1, run).bind(2, int64_t(ord));
    record_insert.bind(3, record.at("technique").get<std::string>())
        .bind(4, record.at("variant").get<std::string>())
        .bind(5, record.at("asset").get<std::string>())
        .bind(6, record.at("parameters").dump())
        .bind(7, record.at("warnings").dump());
    record_insert.run();
    const Json& measures = record.at("measures");
    for (size_t position = 0; position < measures.size(); ++position) {
      const std::string text = measures[position].dump();
      const std::string hash = contentHash(text);
      payload_insert.bind(1, hash).bind(2, text);
      payload_insert.run();
      new_payloads += size_t(sqlite3_changes(db.handle()));
      payload_find.bind(1, hash);
      if (!payload_find.step())
        db.fail("payload " + hash + " not found after insert", SQLITE_ERROR);
      const int64_t payload = payload_find.integer(0);
      payload_find.reset();
      result_insert.bind(1, run).bind(2, int64_t(ord)).bind(3, int64_t(position));
      result_insert.bind(4, measures[position].at("measure").get<std::string>())
          .bind(5, measures[position].at("status").get<std::string>())
          .bind(6, payload);
      result_insert.run();
      ++summary->measure_results;
    }
  }
  summary->records = records.size();
  return new_payloads;
}

void insertTimings(Database& db, int64_t run, const results::RunTimings& timings) {
  Statement insert = db.prepare(
      "INSERT INTO timings(run, position, technique, variant, asset, measure, seconds, samples) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
  for (size_t i = 0; i < timings.measures.size(); ++i) {
    const results::TimingEntry& entry = timings.measures[i];
    insert.bind(1, run).bind(2, int64_t(i)).bind(3, entry.technique).bind(4, entry.variant);
    insert.bind(5, entry.asset).bind(6, entry.measure).bind(7, entry.samples.front());
    insert.bind(8, Json(entry.samples).dump());
    insert.run();
  }
}

std::string runColumns(const HistoryDb& history) {
  return std::string("id, git_sha, ") + (history.version >= 2 ? "commit_time" : "''") +
         ", date, run_id, device, suite, folder";
}

RunInfo runFrom(const Statement& row) {
  return {row.integer(0), row.text(1), row.text(2), row.text(3),
          row.text(4),    row.text(5), row.text(6), row.text(7)};
}

}  // namespace

void setAddHook(AddHook hook) { add_hook = hook; }

AddSummary addRun(HistoryDb& history, const std::string& run_dir) {
  assert(history.db != nullptr && history.version == kHistorySchemaVersion);
  const Json document = readRunDocument(run_dir);
  std::optional<results::RunTimings> timings;
  if (std::filesystem::exists(run_dir + "/timings.json"))
    timings = results::readTimingsFile(run_dir + "/timings.json");
  const Json& context = document.at("context");
  AddSummary summary;
  RunInfo& run = summary.run;
  run.git_sha = context.at("git_sha").get<std::string>();
  run.commit_time = context.value("commit_time", std::string());
  run.date = context.at("date").get<std::string>();
  run.run_id = context.at("run_id").get<std::string>();
  run.device = context.at("vulkan_device").get<std::string>();
  if (run.device.empty()) run.device = "none";
  const Json selection = context.value("selection", Json::object());
  run.suite = selection.value("suite", std::string("default"));
  run.folder = run_dir;
  Json header = Json::object();
  for (const char* key : {"schema_version", "context", "assets", "skipped", "measures"})
    header[key] = document.at(key);

  Database& db = *history.db;
  Transaction transaction(db);
  Statement duplicate =
      db.prepare("SELECT folder FROM runs WHERE git_sha = ? AND run_id = ? AND date = ?");
  duplicate.bind(1, run.git_sha).bind(2, run.run_id).bind(3, run.date);
  if (duplicate.step()) {
    throw HistoryError(fmt::format("{}: run {} (git {}, {}) is already in {} (added from {})",
                                   run_dir, run.run_id, run.git_sha, run.date, db.path(),
                                   duplicate.text(0)));
  }
  Statement insert = db.prepare(
      "INSERT INTO runs(git_sha, commit_time, date, run_id, device, suite, selection, header, "
      "timings, folder) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  insert.bind(1, run.git_sha).bind(2, run.commit_time).bind(3, run.date).bind(4, run.run_id);
  insert.bind(5, run.device).bind(6, run.suite).bind(7, selection.dump()).bind(8, header.dump());
  if (timings) {
    insert.bind(9, Json{{"wall_seconds", timings->wall_seconds},
                        {"threads", timings->threads},
                        {"repetitions", timings->repetitions}}
                       .dump());
  } else {
    insert.bindNull(9);
  }
  insert.bind(10, run_dir);
  insert.run();
  run.id = sqlite3_last_insert_rowid(db.handle());
  insertDeclarations(db, run.id, document.at("measures"));
  summary.new_payloads = insertRecords(db, run.id, document.at("records"), &summary);
  if (timings) {
    insertTimings(db, run.id, *timings);
    summary.timings = timings->measures.size();
  }
  if (add_hook != nullptr) add_hook();
  transaction.commit();
  return summary;
}

std::vector<RunInfo> listRuns(HistoryDb& history) {
  assert(history.db != nullptr);
  Statement query = history.db->prepare("SELECT " + runColumns(history) + " FROM runs");
  std::vector<RunInfo> runs;
  while (query.step()) runs.push_back(runFrom(query));
  std::stable_sort(runs.begin(), runs.end(), [](const RunInfo& a, const RunInfo& b) {
    return std::tie(a.orderTime(), a.date, a.id) < std::tie(b.orderTime(), b.date, b.id);
  });
  return runs;
}

std::vector<RunInfo> findRuns(HistoryDb& history, const std::string& sha_prefix) {
  assert(history.db != nullptr);
  if (sha_prefix.size() < 4) {
    throw HistoryError(sha_prefix + ": give at least 4 characters of a git sha");
  }
  std::vector<RunInfo> found;
  for (RunInfo& run : listRuns(history)) {
    if (run.git_sha.compare(0, sha_prefix.size(), sha_prefix) == 0) found.push_back(std::move(run));
  }
  return found;
}

results::RunData loadRun(HistoryDb& history, int64_t run) {
  assert(history.db != nullptr);
  Database& db = *history.db;
  Statement header_query = db.prepare("SELECT header, timings FROM runs WHERE id = ?");
  header_query.bind(1, run);
  if (!header_query.step()) throw HistoryError(db.path() + ": no run " + std::to_string(run));
  Json document = Json::parse(header_query.text(0));
  const bool has_timings = !header_query.isNull(1);
  const Json timings_header = has_timings ? Json::parse(header_query.text(1)) : Json();
  Json records = Json::array();
  Statement record_query = db.prepare(
      "SELECT technique, variant, asset, parameters, warnings FROM records WHERE run = ? "
      "ORDER BY ord");
  record_query.bind(1, run);
  while (record_query.step()) {
    records.push_back({{"technique", record_query.text(0)},
                       {"variant", record_query.text(1)},
                       {"asset", record_query.text(2)},
                       {"parameters", Json::parse(record_query.text(3))},
                       {"warnings", Json::parse(record_query.text(4))},
                       {"measures", Json::array()}});
  }
  Statement measure_query = db.prepare(
      "SELECT mr.ord, p.json FROM measure_results AS mr JOIN payloads AS p ON p.id = "
      "mr.payload WHERE mr.run = ? ORDER BY mr.ord, mr.position");
  measure_query.bind(1, run);
  while (measure_query.step()) {
    records.at(size_t(measure_query.integer(0)))["measures"].push_back(
        Json::parse(measure_query.text(1)));
  }
  document["records"] = std::move(records);
  results::RunData data{results::resultsFromJson(document), std::nullopt};
  if (has_timings) {
    results::RunTimings timings;
    timings.wall_seconds = timings_header.at("wall_seconds").get<double>();
    timings.threads = timings_header.at("threads").get<int>();
    timings.repetitions = timings_header.at("repetitions").get<int>();
    Statement timing_query = db.prepare(
        "SELECT technique, variant, asset, measure, samples FROM timings WHERE run = ? ORDER BY "
        "position");
    timing_query.bind(1, run);
    while (timing_query.step()) {
      timings.measures.push_back({timing_query.text(0), timing_query.text(1), timing_query.text(2),
                                  timing_query.text(3),
                                  Json::parse(timing_query.text(4)).get<std::vector<double>>()});
    }
    data.timings = std::move(timings);
  }
  return data;
}

std::string runLabel(const RunInfo& run) {
  return run.git_sha.substr(0, 7) + " " + run.orderTime().substr(0, 10);
}

}  // namespace tb::history
