// Fixed-time signal plans evaluated at a time, shifted to start at a scenario's colour.
#include "physics/simulation/traffic_signals.hpp"

#include <cmath>

namespace scenfuzz {

TrafficSignals::TrafficSignals(const RoadMap& map, std::span<const LightSetting> settings) {
  const auto& lights = map.traffic_lights();
  signals_.resize(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    Signal& signal = signals_[i];
    if (lights[i].plan) {
      double period = 0;
      for (const SignalPhase& phase : lights[i].plan->phases) period += phase.duration;
      if (period > 0) {
        signal.plan = lights[i].plan;
        signal.period = period;
      }
    }
  }
  for (const LightSetting& setting : settings) {
    if (setting.light >= signals_.size()) continue;
    Signal& signal = signals_[setting.light];
    signal.fixed = setting.colour;
    if (!signal.plan) continue;
    // Start the cycle at the beginning of the first phase of the scenario's colour.
    double start = 0;
    bool found = false;
    for (const SignalPhase& phase : signal.plan->phases) {
      if (phase.colour == setting.colour) {
        found = true;
        break;
      }
      start += phase.duration;
    }
    if (found) {
      signal.plan->offset = start;
    } else {
      signal.plan.reset();  // the plan never shows that colour: hold it
    }
  }
  // A light without a plan shows one colour throughout: set once, not at every step (Apollo maps
  // have hundreds of lights and no plans).
  colours_.resize(signals_.size(), SignalColour::green);
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    if (signals_[i].plan) {
      planned_.push_back(i);
    } else {
      colours_[i] = signals_[i].fixed;
    }
  }
}

const std::vector<SignalColour>& TrafficSignals::colours_at(double t) {
  for (std::size_t i : planned_) {
    const Signal& signal = signals_[i];
    double in_cycle = std::fmod(t + signal.plan->offset, signal.period);
    if (in_cycle < 0) in_cycle += signal.period;
    SignalColour colour = signal.plan->phases.back().colour;
    for (const SignalPhase& phase : signal.plan->phases) {
      if (in_cycle < phase.duration) {
        colour = phase.colour;
        break;
      }
      in_cycle -= phase.duration;
    }
    colours_[i] = colour;
  }
  return colours_;
}

}  // namespace scenfuzz
