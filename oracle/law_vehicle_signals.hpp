// scenest's law signals that read the ego's own lamps and horn (`turnSignal`, `hornOn`,
// `highBeamOn`, `lowBeamOn`, `fogLightOn`, `warningFlashOn`) and its vehicle status (`engineOn`,
// `manualIntervention`), from the trace's signals column, in LawBreaker's codes: LawBreaker reads
// them from Apollo's chassis message (its VehicleSignal), so a law written for it keeps its
// meaning. docs/oracle.md says what each one is and how it differs. Private to the oracle.
#pragma once

#include <optional>
#include <string_view>

#include "oracle/robustness.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Apollo's VehicleSignal.TurnSignal codes, which `off`, `left` and `right` stand for in a spec.
inline constexpr double kTurnNone = 0, kTurnLeft = 1, kTurnRight = 2;
// Both sides flashing: the hazard lights, or both indicators (TURN_HAZARD_WARNING).
inline constexpr double kTurnHazardWarning = 3;

// Whether `name` is one of these signals.
bool is_vehicle_law_signal(std::string_view name);

// The signal `name` of the trace's ego at every sample (discrete); nullopt when `name` is not one
// of them.
std::optional<SignalValues> vehicle_law_signal(std::string_view name, const Trace& trace);

}  // namespace scenfuzz
