// When each vehicle arrived at the junction it is about to cross or is crossing: the "first come"
// of the junction priority rule (docs/simulation.md, "Junctions"). A vehicle arrives when it
// comes within kArrivalReach of the end of a lane that leads into a junction, or is found on a
// junction lane; it keeps its arrival time until it is on a lane outside any junction again
// farther from one. Computed by the simulation from every actor's lane fix each step, so that
// reactive NPCs can order themselves against each other and the ego without sharing state.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/map/road_map.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// m before a junction's entry from which a vehicle counts as arrived at it.
inline constexpr double kArrivalReach = 12;

// Whether lane `lane`, at lane position `s`, is within kArrivalReach of a junction entry (or in a
// junction).
bool at_junction(const RoadMap& map, LaneFix fix);

class JunctionArrivals {
 public:
  // Moves on to time t: `fixes`, `kinds` and `present` (empty: every actor is) by actor id.
  void update(const RoadMap& map, double t, std::span<const LaneFix> fixes,
              std::span<const TraceActorKind> kinds, std::span<const std::uint8_t> present);
  // By actor id: when it arrived at its junction, NaN when it is at none.
  std::span<const double> arrivals() const { return arrivals_; }

 private:
  std::vector<double> arrivals_;
};

}  // namespace scenfuzz
