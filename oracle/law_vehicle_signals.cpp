// The ego's lamps and horn as LawBreaker's chassis signals. An empty signals column is a run in
// which the ego showed nothing (a driver that sets no signals): every lamp and the horn off.
#include "oracle/law_vehicle_signals.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "lang/demand.hpp"
#include "physics/actors/vehicle_signals.hpp"

namespace scenfuzz {

namespace {

// One lamp or the horn: 1 where its bit is set.
struct LampSignal {
  std::string_view name;
  VehicleSignals bit;
};

constexpr std::array kLamps = {
    LampSignal{"hornOn", vehicle_signal::horn},
    LampSignal{"highBeamOn", vehicle_signal::high_beam},
    LampSignal{"lowBeamOn", vehicle_signal::low_beam},
    LampSignal{"fogLightOn", vehicle_signal::fog_lights},
    LampSignal{"wiperOn", vehicle_signal::wipers},  // CH-Scenario's `wiper`; not LawBreaker's
};

// The simulated ego's engine runs throughout a run, and no safety driver takes over from it.
constexpr double kEngineOn = 1, kNoManualIntervention = 0;

constexpr std::array<std::string_view, 9> kNames = {
    "turnSignal",     "hornOn",   "highBeamOn",         "lowBeamOn", "fogLightOn",
    "warningFlashOn", "engineOn", "manualIntervention", "wiperOn"};

// Apollo's chassis reports both indicator lamps flashing as TURN_HAZARD_WARNING, whichever
// switch lit them: so do we.
bool both_sides_flash(const std::vector<VehicleSignals>& signals, std::size_t i) {
  const bool left = signal_on(signals, i, vehicle_signal::left_indicator);
  const bool right = signal_on(signals, i, vehicle_signal::right_indicator);
  return signal_on(signals, i, vehicle_signal::hazard_lights) || (left && right);
}

double turn_signal(const std::vector<VehicleSignals>& signals, std::size_t i) {
  if (both_sides_flash(signals, i)) return kTurnHazardWarning;
  if (signal_on(signals, i, vehicle_signal::left_indicator)) return kTurnLeft;
  if (signal_on(signals, i, vehicle_signal::right_indicator)) return kTurnRight;
  return kTurnNone;
}

template <typename Value>
SignalValues each_sample(std::size_t count, Value value) {
  SignalValues values{std::vector<double>(count), true};
  for (std::size_t i = 0; i < count; ++i) values.values[i] = value(i);
  return values;
}

}  // namespace

bool is_vehicle_law_signal(std::string_view name) {
  return std::find(kNames.begin(), kNames.end(), name) != kNames.end();
}

std::optional<SignalValues> vehicle_law_signal(std::string_view name, const Trace& trace) {
  const std::size_t count = trace.sample_count();
  const std::vector<VehicleSignals>& signals = trace.actors[kEgo].signals;
  // The column is one per sample or empty (physics/trace/trace.hpp).
  SCENFUZZ_DEMAND(signals.empty() || signals.size() == count);
  if (name == "turnSignal")
    return each_sample(count, [&](std::size_t i) { return turn_signal(signals, i); });
  if (name == "warningFlashOn")
    return each_sample(count,
                       [&](std::size_t i) { return both_sides_flash(signals, i) ? 1.0 : 0.0; });
  for (const LampSignal& lamp : kLamps)
    if (name == lamp.name)
      return each_sample(
          count, [&](std::size_t i) { return signal_on(signals, i, lamp.bit) ? 1.0 : 0.0; });
  if (name == "engineOn") return SignalValues{std::vector<double>(count, kEngineOn), true};
  if (name == "manualIntervention")
    return SignalValues{std::vector<double>(count, kNoManualIntervention), true};
  return std::nullopt;
}

}  // namespace scenfuzz
