// The junction priority rule for a vehicle in a CH-Scenario manoeuvre phase, the lane follower's
// (docs/simulation.md, "Junctions") cut down to what an actor that knows only its lane position
// can see: before a junction it has not entered it stops at the entry while a vehicle (or the
// ego) is inside on a lane crossing or merging with its own, and, turning left, while one comes
// towards a crossing or merging lane that is not a left turn and will be there within the
// give-way time (left turns give way to oncoming traffic). Once inside it has priority over
// everyone still outside. Held standing past its patience it goes on: a car parked in the
// junction does not stop it for ever. A WMG SDL phase, a script against the ego, does not wait.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include "physics/actors/actor_class.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/simulation/lanes_ahead.hpp"
#include "physics/simulation/world_snapshot.hpp"

namespace scenfuzz {

// What the rule remembers between steps for one actor.
struct JunctionWait {
  double held_since = std::numeric_limits<double>::quiet_NaN();  // s, standing held since
  std::optional<LaneIndex> released;  // the junction lane it may enter whatever is inside
};

// The most acceleration (m/s^2, at least minus the class's full braking) that stops actor `self`
// of `world`, at `at` on the lanes `next_lane` picks, at the entry of the junction ahead while
// the rule holds it there; +infinity while it may go on (or is too near the entry to stop).
double junction_entry_limit(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                            const NextLane& next_lane, const ActorClass& body, JunctionWait& wait);

}  // namespace scenfuzz
