// The assembly the ISA measure kept, by file name, for the run command to write under the
// run folder's isa/ (so two runs can be diffed file by file).
#pragma once

#include <map>
#include <string>

namespace tb::measures::isa {

// Keeps `text` as `file_name` (a name already made safe by safeFileName); a later call
// with the same name replaces it (the same pipeline compiled for another record).
void keepAssembly(const std::string& file_name, std::string text);
// Every file kept so far, by name.
std::map<std::string, std::string> keptAssembly();

// `name` with every character outside [A-Za-z0-9._-] replaced by '_'.
std::string safeFileName(std::string name);

}  // namespace tb::measures::isa
