#include "harness/results/device_identity.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

namespace tb::results {

bool measuredOnDevice(const RunContext& context) {
  return !context.vulkan_device.empty() && !context.vulkan_device.starts_with("none");
}

std::optional<std::string> deviceMismatch(const RunContext& base, const RunContext& current) {
  if (!measuredOnDevice(base) || !measuredOnDevice(current)) return std::nullopt;
  if (base.vulkan_device == current.vulkan_device) return std::nullopt;
  return "base measured on '" + base.vulkan_device + "', new on '" + current.vulkan_device +
         "': figures of two devices are never compared";
}

std::string deviceCaveat(const std::string& vulkan_device) {
  std::string name = vulkan_device.substr(0, vulkan_device.find(" ("));
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  constexpr std::array<std::string_view, 9> kDataCentre = {"h100", "h200", "h800", "h20", "a100",
                                                           "a800", "a30",  "b100", "b200"};
  const bool data_centre =
      name.find("nvidia") != std::string::npos &&
      std::any_of(kDataCentre.begin(), kDataCentre.end(), [&](std::string_view part) {
        const size_t at = name.find(part);
        if (at == std::string::npos) return false;
        const size_t end = at + part.size();  // "h20" is not "h200"
        return (at == 0 || !std::isalnum((unsigned char)name[at - 1])) &&
               (end == name.size() || !std::isalnum((unsigned char)name[end]));
      });
  if (!data_centre) return {};
  return "a data-centre GPU with few graphics-capable units (an H100 or H200 exposes two "
         "graphics TPCs): its timings are a lower bound, not a gaming GPU's";
}

}  // namespace tb::results
