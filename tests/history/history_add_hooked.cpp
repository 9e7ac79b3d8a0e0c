// `tessbench history add --db DB RUN` with history::setAddHook's hook set, for the
// concurrency and fault tests (history_cli_test.cpp): `pause=MS` holds the write lock MS ms
// longer (two adds then surely overlap), `kill` sends this process SIGKILL before the commit.
// Exit 0 when added; 2 with one line on stderr otherwise.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <thread>

#include "harness/history/history_store.h"

namespace {

int pause_ms = 0;

void pauseHook() { std::this_thread::sleep_for(std::chrono::milliseconds(pause_ms)); }
void killHook() { ::kill(::getpid(), SIGKILL); }

}  // namespace

int main(int argc, char** argv) {
  const std::string hook = argc == 4 ? argv[1] : "";
  if (hook == "kill") {
    tb::history::setAddHook(killHook);
  } else if (hook.rfind("pause=", 0) == 0) {
    pause_ms = std::stoi(hook.substr(6));
    tb::history::setAddHook(pauseHook);
  } else {
    std::fprintf(stderr, "usage: history_add_hooked pause=MS|kill DB RUN\n");
    return 2;
  }
  try {
    tb::history::HistoryDb history = tb::history::openHistory(argv[2], /*writable=*/true);
    tb::history::addRun(history, argv[3]);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "history_add_hooked: error: %s\n", error.what());
    return 2;
  }
  return 0;
}
