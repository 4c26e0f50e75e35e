// The NPC vehicles' signals at each sample, kept cheap (one or two comparisons a vehicle a
// step): the weather's lights (low beams from dusk and in poor visibility, fog lights, wipers),
// brake lights, and the indicators before and through the lane changes and junction turns of a
// lane route (lane followers, scripted lane drives, background traffic, from
// route_indications.hpp) or of a manoeuvre phase (ManoeuvreDriver::indicator). Vehicles on a
// waypoint path do not indicate. docs/simulation.md ("Vehicle signals") has the figures.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "physics/ego/signal_policy.hpp"
#include "physics/simulation/lane_follower.hpp"
#include "physics/simulation/manoeuvre_driver.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/traffic_flows.hpp"

namespace scenfuzz {

class NpcSignals {
 public:
  // For the scenario's actors (setup.actors) and the flow vehicles of `flow_vehicles`.
  NpcSignals(const RoadMap& map, const SimulationSetup& setup,
             const std::vector<FlowVehicle>& flow_vehicles, const SignalWeather& weather,
             const SignalSettings& settings = {});

  // Scenario actor i (setup.actors[i]) at time t, in `state`: driven by `follower` or `driver`
  // when not null, else scripted. 0 for pedestrians.
  VehicleSignals scenario_actor(std::size_t i, double t, const KinematicState& state,
                                const LaneFollower* follower, const ManoeuvreDriver* driver);
  // Flow vehicle j in `state`, driven by `follower` while on the map (0 while it is not).
  VehicleSignals flow_vehicle(std::size_t j, const KinematicState& state,
                              const LaneFollower* follower);

 private:
  VehicleSignals along_route(const std::vector<IndicationStretch>& stretches,
                             IndicationCursor& cursor, double progress, double speed) const;

  const SimulationSetup* setup_;
  SignalSettings settings_;
  VehicleSignals weather_ = 0;
  // By scenario actor: its lane drive's stretches (empty without one), cursor, whether it moved.
  std::vector<std::vector<IndicationStretch>> actor_stretches_;
  std::vector<IndicationCursor> actor_cursors_;
  std::vector<std::uint8_t> moved_;
  // By flow: its route's stretches; by flow vehicle: its flow and cursor.
  std::vector<std::vector<IndicationStretch>> flow_stretches_;
  std::vector<std::size_t> vehicle_flow_;
  std::vector<IndicationCursor> vehicle_cursors_;
};

}  // namespace scenfuzz
