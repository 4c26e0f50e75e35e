// Vehicle signal names (vehicle_signal_names.hpp).
#include "physics/actors/vehicle_signal_names.hpp"

#include <array>

namespace scenfuzz {
namespace {

// In bit order: kNames[b] names the bit 1 << b.
constexpr std::array<std::string_view, 9> kNames{
    "left_indicator", "right_indicator", "hazard_lights", "horn",        "low_beam",
    "high_beam",      "fog_lights",      "wipers",        "brake_lights"};
static_assert((1u << kNames.size()) - 1 == vehicle_signal::all);

}  // namespace

std::string_view vehicle_signal_name(VehicleSignals bit) {
  for (std::size_t b = 0; b < kNames.size(); ++b)
    if (bit == (1u << b)) return kNames[b];
  return {};
}

std::string vehicle_signal_list(VehicleSignals signals) {
  std::string list;
  for (std::size_t b = 0; b < kNames.size(); ++b) {
    if ((signals & (1u << b)) == 0) continue;
    if (!list.empty()) list += '|';
    list += kNames[b];
  }
  return list;
}

std::optional<VehicleSignals> parse_vehicle_signal_list(std::string_view text) {
  VehicleSignals signals = 0;
  while (!text.empty()) {
    const std::size_t bar = text.find('|');
    const std::string_view name = text.substr(0, bar);
    std::size_t b = 0;
    while (b < kNames.size() && kNames[b] != name) ++b;
    if (b == kNames.size()) return std::nullopt;
    signals |= static_cast<VehicleSignals>(1u << b);
    if (bar == std::string_view::npos) break;
    text.remove_prefix(bar + 1);
    if (text.empty()) return std::nullopt;  // a trailing '|'
  }
  return signals;
}

}  // namespace scenfuzz
