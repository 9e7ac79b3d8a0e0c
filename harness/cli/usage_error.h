// Bad command-line input (a flag or an option's value), apart from bad input files
// (mesh::InputError): what() is one line naming the option and the rule; main prints it and
// exits 2.
#pragma once

#include <stdexcept>
#include <string>

#include "core/mesh/input_error.h"

namespace tb::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  // "option: value: rule" (the empty parts left out), as mesh::InputError words a file's.
  UsageError(const std::string& option, const std::string& value, const std::string& rule)
      : std::runtime_error(mesh::inputErrorMessage(option, value, rule)) {}
};

}  // namespace tb::cli
