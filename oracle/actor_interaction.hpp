// Whether a scenario's actors ever come near the ego at all: a sanity check every run gets. A
// scenario whose actors all stay metres away from wherever the ego drives (an author's layout read
// differently than meant, a pedestrian walking away from every road) can never fail, so a search
// over it reports "0 findings" as if the ego had passed: a silent wrong answer. `run` and the
// search warn instead, with the nearest each actor came.
#pragma once

#include <string>
#include <vector>

#include "physics/trace/trace.hpp"

namespace scenfuzz {

// m between bodies: an actor whose body came this near the ego's path interacts with the ego.
inline constexpr double kInteractionReach = 3.0;

// The nearest an actor's body came to the ego's path (the ground the ego's body covered over the
// run, whenever it covered it, and the 3 s ahead of it at its last speed and heading), and when.
struct ActorApproach {
  ActorId actor = kEgo;
  double gap = 0;   // m between the bodies' outer circles and the path; 0 when they overlap
  double time = 0;  // s
};

// One per actor other than the ego that is ever on the map, in the trace's order.
std::vector<ActorApproach> actor_approaches(const Trace& trace);

// Whether some approach came within kInteractionReach (true when there are no other actors:
// nothing to meet is not a layout that went wrong).
bool actors_interact(const std::vector<ActorApproach>& approaches);

// "the scenario's actors never come within 3 m of the ego's path (npc1 42.1 m at 12.3 s, ...)",
// or empty when they interact.
std::string no_interaction_warning(const Trace& trace,
                                   const std::vector<ActorApproach>& approaches);

}  // namespace scenfuzz
