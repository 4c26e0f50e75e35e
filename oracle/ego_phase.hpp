// The coarse manoeuvre phase a failure mode is keyed by (oracle/failure_mode.hpp). The finer
// EgoActivity labels flicker between runs of one failure: an ego that pulls out round a stopped
// car and clips it is "pulling out" in one run and "changing lane" in the next, and "following"
// and "cruising" swap with the 3 s reach. A phase merges the labels that are one manoeuvre and
// looks over a window of the trace instead of at one sample, so that one failure keeps one phase.
#pragma once

#include <cstddef>
#include <string_view>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// The first that applies, in this order.
enum class EgoPhase {
  reversing,
  standing,      // slower than kEgoStoppedSpeed (failure_mode.hpp)
  turning_left,  // on a junction lane that turns left (right, back)
  turning_right,
  turning_around,
  leaving_lane,  // within kLaneChangeWindow either side: on a forward neighbour of its lane, on
                 // no lane, or swerving (kSwerveHeading off its lane's direction or kSwerveOffset
                 // off its centre line): lane changes, overtaking, pulling out round something
  in_lane,       // everything else: cruising, following, moving off in its lane
};

inline constexpr double kSwerveHeading = 0.1;  // rad, about 6 degrees
inline constexpr double kSwerveOffset = 1.0;   // m

std::string_view ego_phase_name(EgoPhase phase);

// The ego's phase at `sample` of the trace.
EgoPhase ego_phase_at(const Trace& trace, const RoadMap& map, std::size_t sample);

}  // namespace scenfuzz
