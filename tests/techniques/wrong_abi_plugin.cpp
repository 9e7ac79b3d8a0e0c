// A plug-in built against another ABI: its handshake reports kTessbenchPluginAbi + 1, and its
// registration entry aborts the process, so a host that called it after a mismatch (or
// before asking) fails the test loudly instead of quietly registering.
#include <cstdlib>

#include "techniques/plugin.h"

extern "C" __attribute__((visibility("default"))) int tessbench_plugin_abi() {
  return kTessbenchPluginAbi + 1;
}

extern "C" __attribute__((visibility("default"))) void tessbench_register_plugin(
    tb::techniques::PluginHost*) {
  std::abort();
}
