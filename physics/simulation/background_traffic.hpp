// Background traffic in the simulation loop: the vehicles a run's flows send (traffic_flows.hpp),
// each an actor of the trace from the first sample, on the map only between its entry and its
// exit. Each step, those that drove off their route's end leave, the arrivals that are due enter
// at their route's start once nothing stands within their safe gap there (until then they wait,
// in order, as a queue spilling back off the map), no faster than what is ahead of the entry, and
// those on the map drive as reactive lane followers. Outside its presence a vehicle rests at its
// entry pose (before) or its exit pose (after), disabled in the collision world.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "physics/collision/collision_world.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/lane_follower.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/traffic_flows.hpp"
#include "physics/simulation/world_snapshot.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

class BackgroundTraffic {
 public:
  // The vehicles of `schedule` are actors first, first + 1, ... of the run (and bodies of the
  // same ids in the collision world); `setup` and `map` must outlive this.
  BackgroundTraffic(const RoadMap& map, const SimulationSetup& setup, FlowSchedule schedule,
                    std::size_t first);

  bool empty() const { return vehicles_.empty(); }
  std::size_t size() const { return vehicles_.size(); }
  const FlowVehicle& vehicle(std::size_t j) const { return vehicles_[j]; }
  const std::vector<FlowVehicle>& vehicles() const { return vehicles_; }
  // Where vehicle j is before its first step (its entry pose, at rest, while it is not yet on
  // the map).
  KinematicState initial_state(std::size_t j) const;
  bool present_at_start(std::size_t j) const { return followers_[j].has_value(); }
  // Vehicle j's driver while it is on the map, else null.
  const LaneFollower* follower(std::size_t j) const {
    return followers_[j] ? &*followers_[j] : nullptr;
  }

  // At sample `step` (time t): vehicles that have left are taken out, due arrivals whose entry is
  // clear come in; every flow vehicle's state, present flag (both by actor id) and body in
  // `world` follow. `states` must hold every other actor's state at t.
  void update(std::size_t step, double t, std::span<KinematicState> states,
              std::span<const double> lengths, std::span<const double> widths,
              std::span<std::uint8_t> present, CollisionWorld& world);

  // The vehicles on the map react to the world as it is now and move on by dt.
  void step(const WorldSnapshot& world, double dt);

  // Writes each vehicle's presence interval into its trace actor at the end of a run of
  // `samples` samples; one still waiting then never got in (an empty interval at the end).
  void finish(std::span<TraceActor> actors, std::size_t samples) const;

 private:
  LaneFollower make_follower(std::size_t j, double speed) const;

  const RoadMap* map_;
  const SimulationSetup* setup_;
  std::vector<FlowVehicle> vehicles_;
  std::size_t first_;
  std::vector<std::optional<LaneFollower>> followers_;  // while on the map
  std::vector<std::size_t> from_, until_;               // presence, as TraceActor's
  // Per flow: its vehicles still to come, in order (indices into vehicles_), and the next one.
  std::vector<std::vector<std::size_t>> queues_;
  std::vector<std::size_t> next_;
};

}  // namespace scenfuzz
