// Typed access to a variant's numeric parameters (VariantInfo::parameters), so no
// technique parses the map by hand. Parameters are doubles in the map; param<T> converts:
// bool is "!= 0", an integer or enum type needs an integral value.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "techniques/technique.h"

namespace tb::techniques {

// Thrown when a variant lacks a parameter its technique reads, or holds a value of the
// wrong kind. The message names technique, variant and parameter:
// "phong/alpha0.75: variant parameter 'alpha' is missing".
class VariantParameterError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace detail {
[[noreturn]] void throwVariantParameterError(const TechniqueInfo& technique,
                                             const VariantInfo& variant, std::string_view name,
                                             const std::string& problem);

template <class T>
T convertParameter(const TechniqueInfo& technique, const VariantInfo& variant,
                   std::string_view name, double value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value != 0.0;
  } else if constexpr (std::is_floating_point_v<T>) {
    return T(value);
  } else {
    static_assert(std::is_integral_v<T> || std::is_enum_v<T>, "param<T>: numeric or enum T");
    if (std::trunc(value) != value) {
      throwVariantParameterError(technique, variant, name,
                                 "is " + std::to_string(value) + ", not an integer");
    }
    return T(static_cast<long long>(value));
  }
}
}  // namespace detail

// The parameter `name` of `variant`; VariantParameterError when it is missing.
template <class T>
T param(const TechniqueInfo& technique, const VariantInfo& variant, std::string_view name) {
  const auto it = variant.parameters.find(std::string(name));
  if (it == variant.parameters.end()) {
    detail::throwVariantParameterError(technique, variant, name, "is missing");
  }
  return detail::convertParameter<T>(technique, variant, name, it->second);
}

// The parameter `name` of `variant`, or `fallback` when the variant does not set it.
template <class T>
T paramOr(const TechniqueInfo& technique, const VariantInfo& variant, std::string_view name,
          T fallback) {
  const auto it = variant.parameters.find(std::string(name));
  if (it == variant.parameters.end()) return fallback;
  return detail::convertParameter<T>(technique, variant, name, it->second);
}

}  // namespace tb::techniques
