// Whose fault a collision with the ego is: `ego`, `other` or `shared`, decided with the rules of
// Responsibility-Sensitive Safety and what RSS leaves to the map (lights, signs, priority), with
// one sentence of reason and the numbers a user triages it by. docs/oracle.md, "Responsibility",
// has the rules in order.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "oracle/path_entry.hpp"
#include "oracle/rss_parameters.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

enum class Responsibility { ego, other, shared };

// "ego", "other", "shared".
std::string_view responsibility_name(Responsibility responsibility);

// Whether the ego is to blame, alone or not: what the collision oracle counts.
inline bool ego_responsible(Responsibility responsibility) {
  return responsibility != Responsibility::other;
}

struct CollisionTriage {
  double ego_speed = 0;               // m/s at impact
  double ego_acceleration = 0;        // m/s^2 at impact, negative braking
  double relative_speed = 0;          // m/s, magnitude of the velocity difference at impact
  double impact_angle = 0;            // degrees in [0, 180], between the two headings at impact
  bool ego_stationary = false;        // standing still at impact
  bool ego_braking_at_limit = false;  // braking within 5 % of its class's full braking
  // The other's last manoeuvre: when it came into the ego's path, and the room left then.
  std::optional<PathEntry> entry;
};

struct CollisionResponsibility {
  std::size_t collision = 0;  // index into Trace::collisions
  ActorId other = kEgo;       // the ego's counterpart
  Responsibility responsibility = Responsibility::ego;
  std::string reason;  // one sentence, no final full stop
  CollisionTriage triage;
  // When the danger began with a sideways move (RSS's lateral case): that sample. A lane change
  // that ends in a collision seconds later is one failure whether the impact comes while the ego
  // is still leaving its lane or after it settled, so its phase is read here (failure_mode.hpp).
  std::optional<std::size_t> danger_began;
};

// The responsibility for collision `index` of `trace`, which must involve the ego. `map` is the
// map the trace was simulated on.
CollisionResponsibility collision_responsibility(const Trace& trace, const RoadMap& map,
                                                 std::size_t index, const RssParameters& rss);

// One per collision of the ego, in the trace's order.
std::vector<CollisionResponsibility> ego_collision_responsibilities(const Trace& trace,
                                                                    const RoadMap& map,
                                                                    const RssParameters& rss);

}  // namespace scenfuzz
