#include "harness/measures/common/isa/isa_assembly.h"

#include <cctype>
#include <mutex>
#include <utility>

namespace tb::measures::isa {
namespace {

struct Store {
  std::mutex mutex;
  std::map<std::string, std::string> files;
};

Store& store() {
  static Store s;
  return s;
}

}  // namespace

void keepAssembly(const std::string& file_name, std::string text) {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  s.files[file_name] = std::move(text);
}

std::map<std::string, std::string> keptAssembly() {
  Store& s = store();
  const std::lock_guard lock(s.mutex);
  return s.files;
}

std::string safeFileName(std::string name) {
  for (char& c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (!std::isalnum(u) && c != '.' && c != '_' && c != '-') c = '_';
  }
  return name;
}

}  // namespace tb::measures::isa
