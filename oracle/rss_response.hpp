// RSS's blame for two road users on the same or opposite directions (Shalev-Shwartz et al. 2017,
// definitions 5-8): a situation is dangerous when both the longitudinal and the lateral distance
// are below their safe values; the blame time is the start of the dangerous stretch that ends in
// the collision; and from it each party owes the proper response: the distance that became unsafe
// last decides which (longitudinal: the rear brakes at >= brake_min after its response time, the
// front brakes no harder than brake_max; lateral: each keeps its sideways acceleration within
// lateral_accel_max during its response time and then brakes sideways at >= lateral_brake_min).
// A party that did not is to blame. Private to the responsibility oracle.
#pragma once

#include <cstddef>
#include <vector>

#include "oracle/rss_parameters.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// Which distance became unsafe last; `from_start`: the pair was in danger from its first sample,
// so both responses are owed.
enum class RssCase { longitudinal, lateral, from_start };

struct BlameTime {
  std::size_t sample = 0;
  RssCase which = RssCase::from_start;
};

// The blame time of the collision between the ego and `other` at `collision_sample`.
BlameTime rss_blame_time(const Trace& trace, const RoadMap& map, ActorId other,
                         std::size_t collision_sample, const RssParameters& rss);

enum class ResponseFault {
  accelerated,     // accelerated beyond accel_max within its response time while owing braking
  did_not_brake,   // braked less than brake_min (brake_min_correct facing oncoming) after it
  braked_hard,     // a leader braking harder than brake_max
  reversed,        // a leader reversing into the one behind
  moved_sideways,  // sideways towards the other beyond what the lateral response allows
};

struct ResponseViolation {
  ActorId actor = kEgo;
  ResponseFault fault = ResponseFault::did_not_brake;
  std::size_t sample = 0;  // where it first showed
  double value = 0;        // the offending acceleration (m/s^2) or sideways speed (m/s)
  double limit = 0;        // what the response allowed
};

// The response time RSS gives `actor`: rho_ego for the ego, rho_other for the rest.
double rss_response_time(ActorId actor, const RssParameters& rss);

// Whether the ego is the rear one at the blame time (same direction) .
bool ego_is_behind(const Trace& trace, const RoadMap& map, ActorId other, std::size_t sample);

// Whether the pair drives in opposite directions at `sample`.
bool opposite_directions(const Trace& trace, const RoadMap& map, ActorId other, std::size_t sample);

// Every improper response from the blame time to the collision, of both parties.
std::vector<ResponseViolation> rss_improper_responses(const Trace& trace, const RoadMap& map,
                                                      ActorId other, const BlameTime& blame,
                                                      std::size_t collision_sample,
                                                      const RssParameters& rss);

// Whether `actor` braked properly from `from` (a sample) to `collision_sample`: after its response
// time its speed fell by at least `brake` per second on average (within 10 %), or it stood still.
// True when less than two samples of the window follow the response time: nothing was owed yet.
bool braked_properly(const Trace& trace, ActorId actor, std::size_t from,
                     std::size_t collision_sample, double brake, const RssParameters& rss);

}  // namespace scenfuzz
