// The signals a vehicle shows other road users: indicators, hazard lights, horn, beams, fog
// lights, wipers and brake lights, as one bit set per trace sample. The bit values are the ego
// plugin ABI's SCENFUZZ_SIGNAL_* (physics/ego/ego_plugin.h), so a plugin's word is stored as is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace scenfuzz {

using VehicleSignals = std::uint16_t;

namespace vehicle_signal {
inline constexpr VehicleSignals left_indicator = 1u << 0;
inline constexpr VehicleSignals right_indicator = 1u << 1;
inline constexpr VehicleSignals hazard_lights = 1u << 2;  // both indicators flashing
inline constexpr VehicleSignals horn = 1u << 3;
inline constexpr VehicleSignals low_beam = 1u << 4;
inline constexpr VehicleSignals high_beam = 1u << 5;
inline constexpr VehicleSignals fog_lights = 1u << 6;
inline constexpr VehicleSignals wipers = 1u << 7;
inline constexpr VehicleSignals brake_lights = 1u << 8;
inline constexpr VehicleSignals all = (1u << 9) - 1;
}  // namespace vehicle_signal

// Whether `signal` is on at sample i of a signals column (a TraceActor's; empty: all off).
inline bool signal_on(const std::vector<VehicleSignals>& signals, std::size_t i,
                      VehicleSignals signal) {
  return !signals.empty() && (signals[i] & signal) != 0;
}

}  // namespace scenfuzz
