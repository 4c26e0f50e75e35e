// The colour each of the map's traffic lights shows at a time: its fixed-time plan, started at
// the scenario's initial colour when the scenario sets one. A light without a plan (Apollo maps
// carry none) shows the scenario's colour throughout, or green when the scenario says nothing.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "physics/map/road_map.hpp"
#include "physics/simulation/scenario_setup.hpp"

namespace scenfuzz {

class TrafficSignals {
 public:
  TrafficSignals(const RoadMap& map, std::span<const LightSetting> settings);

  // Every light's colour at time t (index as the map's traffic_lights()).
  const std::vector<SignalColour>& colours_at(double t);

 private:
  struct Signal {
    std::optional<SignalPlan> plan;
    SignalColour fixed = SignalColour::green;  // without a plan
    double period = 0;
  };
  std::vector<Signal> signals_;
  std::vector<std::size_t> planned_;  // the signals with a plan; the others' colours never change
  std::vector<SignalColour> colours_;
};

}  // namespace scenfuzz
