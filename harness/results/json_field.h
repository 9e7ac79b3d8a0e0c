// Reading a required field of results.json, naming the path to it when it is missing or
// mistyped. Internal to harness/results.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace tb::results::json_detail {

template <class T>
T field(const nlohmann::ordered_json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) {
    throw std::runtime_error(where + ": missing field '" + key + "'");
  }
  try {
    return object.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error(where + ": field '" + key + "' has the wrong type");
  }
}

}  // namespace tb::results::json_detail
