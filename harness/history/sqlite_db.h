// A thin RAII layer over SQLite's C API (Debian's libsqlite3): a connection and prepared
// statements, every error thrown as one line naming the database file. No ORM: the history
// store (history_store.h) writes its SQL itself.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace tb::history {

// Bad input about a history database (not a SQLite file, another schema, a run already
// added, an unknown sha): one line; the CLI prints it and exits 2.
class HistoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Statement;

class Database {
 public:
  enum class Mode { kReadOnly, kReadWrite, kCreate };
  // Opens `path`; throws HistoryError naming it when SQLite cannot. Sets a busy timeout of
  // `busy_timeout_ms` so that concurrent writers wait for each other instead of failing.
  Database(const std::string& path, Mode mode, int busy_timeout_ms = 120000);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  const std::string& path() const { return path_; }
  sqlite3* handle() const { return db_; }
  // Runs one or more statements without results; throws naming the file and the SQL's start.
  void exec(std::string_view sql);
  Statement prepare(std::string_view sql);
  // Throws HistoryError "<path>: <what>: <sqlite message>" for a failed call's code.
  [[noreturn]] void fail(std::string_view what, int code) const;

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

// A prepared statement; bind parameters are numbered from 1, columns from 0.
class Statement {
 public:
  Statement(Database& db, std::string_view sql);
  ~Statement();
  Statement(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, int64_t value);
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bindNull(int index);
  // One step: true while a row is there to read, false when done.
  bool step();
  // Steps a statement that returns no rows, then resets it for the next bindings.
  void run();
  void reset();

  int64_t integer(int column) const;
  double real(int column) const;
  std::string text(int column) const;  // "" for NULL
  bool isNull(int column) const;
  int columnCount() const { return sqlite3_column_count(statement_); }

 private:
  Database* db_;
  sqlite3_stmt* statement_ = nullptr;
};

}  // namespace tb::history
