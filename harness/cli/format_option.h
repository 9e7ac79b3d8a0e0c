// The spellings of --format values the subcommands share: `markdown` is the one they print
// (help, defaults); `md` is accepted for it.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>

namespace tb::cli {

// Rewrites `md` to `markdown` and passes any other value through unchanged (the subcommand
// names the known formats when it refuses one). Adds nothing to the option's help.
inline CLI::Validator markdownAlias() {
  return CLI::Transformer(std::map<std::string, std::string>{{"md", "markdown"}}).description("");
}

}  // namespace tb::cli
