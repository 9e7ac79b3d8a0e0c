// Where the build put the source checkout, the build tree and the binaries the tests run.
// Only tests/test_paths.cpp reads them, from a header the build generates (tests/CMakeLists.txt),
// so that no other test file's compile command or preprocessed text carries an absolute path:
// ccache then reuses every other test object in another clone of the repository (CI's).
#pragma once

namespace tb::testing {

const char* sourceDir();       // the source checkout (assets/, results/baseline/, ...)
const char* binaryDir();       // the build tree
const char* tessbenchBin();    // the tessbench executable of this build
const char* examplePlugin();   // examples' plug-in, built by tests/techniques
const char* wrongAbiPlugin();  // a plug-in reporting another ABI (tests/techniques)
const char* regressGood();     // compare's acceptance plug-in, as it is (tests/cli)
const char* regressBroken();   // the same source built broken (tests/cli)
// `history add` with a test's hook (tests/history/history_add_hooked.cpp)
const char* historyAddHooked();

}  // namespace tb::testing

// The names the tests have always used. (The regress plug-ins' paths have none: TB_REGRESS_BROKEN
// is the flag regress_plugin.cpp is built broken with.)
#define TB_SOURCE_DIR (::tb::testing::sourceDir())
#define TB_BINARY_DIR (::tb::testing::binaryDir())
#define TB_TESSBENCH_BIN (::tb::testing::tessbenchBin())
#define TB_EXAMPLE_PLUGIN (::tb::testing::examplePlugin())
#define TB_WRONG_ABI_PLUGIN (::tb::testing::wrongAbiPlugin())
