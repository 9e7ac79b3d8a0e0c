#include "core/mesh/input_error.h"

namespace tb::mesh {

std::string inputErrorMessage(const std::string& file, const std::string& element,
                              const std::string& rule) {
  std::string message = file;
  for (const std::string* part : {&element, &rule}) {
    if (part->empty()) continue;
    if (!message.empty()) message.append(": ");
    message.append(*part);
  }
  return message;
}

InputError::InputError(std::string file, std::string element, std::string rule)
    : std::runtime_error(inputErrorMessage(file, element, rule)),
      file_(std::move(file)),
      element_(std::move(element)),
      rule_(std::move(rule)) {}

}  // namespace tb::mesh
