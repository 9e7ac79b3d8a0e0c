// The one exception type for bad input: it names the file, the element (line,
// face, vertex, edge, option) and the rule that was broken, so the CLI can print
// a single line and exit non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace tb::mesh {

// "file: element: rule", leaving out the empty parts: InputError's message (and the CLI's
// usage errors', harness/cli/usage_error.h).
std::string inputErrorMessage(const std::string& file, const std::string& element,
                              const std::string& rule);

class InputError : public std::runtime_error {
 public:
  // file: path or asset name; element: "line 12", "face 17", "vertex 3", ...;
  // rule: what was expected, in words.
  InputError(std::string file, std::string element, std::string rule);

  const std::string& file() const { return file_; }
  const std::string& element() const { return element_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string file_, element_, rule_;
};

}  // namespace tb::mesh
