// Names of domains and spacings as they appear on the command line and in results:
// the HLSL attribute spellings ("tri", "quad", "isoline"; "integer", "pow2",
// "fractional_odd", "fractional_even").
#include <array>
#include <utility>

#include "core/tess/tessellator.h"

namespace tb::tess {
namespace {

constexpr std::array<std::pair<Domain, std::string_view>, 3> kDomainNames{{
    {Domain::kTriangle, "tri"},
    {Domain::kQuad, "quad"},
    {Domain::kIsoline, "isoline"},
}};

constexpr std::array<std::pair<Spacing, std::string_view>, 4> kSpacingNames{{
    {Spacing::kInteger, "integer"},
    {Spacing::kPow2, "pow2"},
    {Spacing::kFractionalOdd, "fractional_odd"},
    {Spacing::kFractionalEven, "fractional_even"},
}};

template <typename Enum, size_t kCount>
std::string_view nameOf(const std::array<std::pair<Enum, std::string_view>, kCount>& names,
                        Enum value) {
  for (const auto& [v, name] : names) {
    if (v == value) return name;
  }
  return "unknown";
}

template <typename Enum, size_t kCount>
bool valueOf(const std::array<std::pair<Enum, std::string_view>, kCount>& names,
             std::string_view name, Enum* out) {
  for (const auto& [v, n] : names) {
    if (n == name) {
      *out = v;
      return true;
    }
  }
  return false;
}

}  // namespace

std::string_view toString(Domain d) { return nameOf(kDomainNames, d); }
std::string_view toString(Spacing s) { return nameOf(kSpacingNames, s); }
bool parseDomain(std::string_view name, Domain* out) { return valueOf(kDomainNames, name, out); }
bool parseSpacing(std::string_view name, Spacing* out) { return valueOf(kSpacingNames, name, out); }

}  // namespace tb::tess
