// The NPC vehicles' signals at each sample: the weather's lights (low beams from dusk and in poor
// visibility, fog lights, wipers), brake lights, and the indicators before and through the lane
// changes and junction turns of a lane route (lane followers, scripted lane drives, background
// traffic, from route_indications.hpp), of a waypoint path (path_indications.hpp) or of a
// manoeuvre phase (ManoeuvreDriver::indicator). docs/simulation.md ("Vehicle signals") has the
// figures. Kept cheap: during the run only the vehicles with something to indicate are looked
// at; the lights and brake lights, which the trace's own columns decide, are added when the run
// ends. Only a plugin reads other vehicles' signals during the run (perception passes them on):
// with one, every vehicle's signals are worked out at every step.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "physics/ego/signal_policy.hpp"
#include "physics/simulation/background_traffic.hpp"
#include "physics/simulation/lane_follower.hpp"
#include "physics/simulation/manoeuvre_driver.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/traffic_flows.hpp"

namespace scenfuzz {

class NpcSignals {
 public:
  // For the scenario's actors (setup.actors; followers[i] set where actor i drives reactively)
  // and the flow vehicles of `flow_vehicles`.
  NpcSignals(const RoadMap& map, const SimulationSetup& setup,
             const std::vector<std::optional<LaneFollower>>& followers,
             const std::vector<FlowVehicle>& flow_vehicles, const SignalWeather& weather,
             const SignalSettings& settings = {});

  // At sample time t (the next sample: called once for each): the indicators of the NPC vehicles
  // that indicate along the way, noted where they change, and when `truth` is not null (a plugin
  // watches) every NPC vehicle's signals set in what perception sees of it (actors 1, 2, ... in
  // order). Scenario actor i is
  // actor i + 1, driven by followers[i] or drivers[i] when set, else scripted; flow vehicle j is
  // actor first_flow + j, there while traffic.follower(j) is (no signals while it is not).
  void record(double t, std::span<const KinematicState> states,
              const std::vector<std::optional<LaneFollower>>& followers,
              const std::vector<std::optional<ManoeuvreDriver>>& drivers,
              const BackgroundTraffic& traffic, std::size_t first_flow,
              std::vector<WorldObject>* truth);

  // When the run has ended (after BackgroundTraffic::finish): every NPC vehicle's column written,
  // its indicators as noted, its lights and brake lights from its speed and acceleration columns.
  void finish(std::vector<TraceActor>& actors, std::size_t first_flow) const;

 private:
  // What each scenario actor needs looked at.
  struct Slot {
    bool vehicle = false;    // pedestrians have no signals
    bool driven = false;     // reactive (a lane follower, manoeuvre phases): holds the brake
                             // whenever it stands; a scripted one only once it has moved
    bool moved = false;      // so far in the run (for `truth`)
    bool indicates = false;  // a lane route or waypoint path with something to indicate, or
                             // manoeuvre phases
  };

  VehicleSignals brake(double acceleration, double speed, bool held) const {
    const bool braking = acceleration < -settings_.braking;
    const bool standing = held && std::abs(speed) < settings_.standing;
    return braking || standing ? vehicle_signal::brake_lights : VehicleSignals{0};
  }
  VehicleSignals actor_indicator(std::size_t i, double t, const KinematicState& state,
                                 const LaneFollower* follower, const ManoeuvreDriver* driver);
  VehicleSignals flow_indicator(std::size_t j, const KinematicState& state,
                                const LaneFollower& follower);
  // Notes actor k's indicator at this sample where it changed.
  void note(std::size_t k, VehicleSignals indicator) {
    if (indicator == indicators_[k]) return;
    indicators_[k] = indicator;
    changes_.push_back({k, sample_, indicator});
  }
  // Every NPC vehicle's signals now into `truth`, its indicator as noted this step.
  void set_truth(std::span<const KinematicState> states, const BackgroundTraffic& traffic,
                 std::size_t first_flow, std::vector<WorldObject>& truth);
  // Lights and brake lights over a finished column, in samples [from, until) (on the map).
  void complete(TraceActor& actor, bool driven, std::size_t from, std::size_t until) const;

  // An indicator change: actor `actor` shows `indicator` from sample `sample` on.
  struct Change {
    std::size_t actor = 0;
    std::size_t sample = 0;
    VehicleSignals indicator = 0;
  };

  const SimulationSetup* setup_;
  SignalSettings settings_;
  VehicleSignals lights_ = 0;            // the weather's, the same for all
  std::vector<Slot> slots_;              // by scenario actor
  std::vector<std::size_t> indicating_;  // the scenario actors whose slot indicates, in order
  // By scenario actor: its lane drive's or waypoint path's stretches (empty without one) and
  // cursor.
  std::vector<std::vector<IndicationStretch>> actor_stretches_;
  std::vector<IndicationCursor> actor_cursors_;
  // By flow: its route's stretches; by flow vehicle: its flow and cursor.
  std::vector<std::vector<IndicationStretch>> flow_stretches_;
  std::vector<std::size_t> vehicle_flow_;
  std::vector<IndicationCursor> vehicle_cursors_;
  std::size_t sample_ = 0;                  // the sample record() is at
  std::vector<VehicleSignals> indicators_;  // by actor id: its indicator now
  std::vector<Change> changes_;             // in sample order
};

}  // namespace scenfuzz
