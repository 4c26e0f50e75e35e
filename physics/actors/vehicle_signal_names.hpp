// The names of the vehicle signals (vehicle_signals.hpp) as traces and reports write them:
// "left_indicator", "low_beam", ... and a set of them joined by '|'.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "physics/actors/vehicle_signals.hpp"

namespace scenfuzz {

// The name of one signal bit; empty for a value that is not exactly one known bit.
std::string_view vehicle_signal_name(VehicleSignals bit);

// The names of the bits on, in bit order, joined by '|' ("left_indicator|low_beam"); empty for
// none.
std::string vehicle_signal_list(VehicleSignals signals);

// The signals a list written by vehicle_signal_list names; nullopt for an unknown name.
std::optional<VehicleSignals> parse_vehicle_signal_list(std::string_view text);

}  // namespace scenfuzz
