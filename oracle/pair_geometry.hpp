// Two traced actors at one sample seen in one frame: the gaps between their bodies along and
// across it, and their velocities in it. RSS measures in lane coordinates; the frame here is the
// reference actor's lane direction where it follows its lane (else its heading), and each actor's
// lateral velocity is taken against its own lane, so that cars on neighbouring lanes of a bend do
// not seem to move sideways. Private to the responsibility oracle.
#pragma once

#include <cstddef>
#include <optional>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct PairGeometry {
  double frame_heading = 0;  // rad, the frame's x axis
  double dx = 0;             // the other's centre ahead of the reference's (m, along the frame)
  double dy = 0;             // to its left (m)
  double gap_lon = 0;        // between the bodies along the frame; negative: side by side
  double gap_lat = 0;        // across it; negative: overlapping sideways (in each other's path)
  double reference_lon = 0;  // velocities (m/s): along the frame,
  double other_lon = 0;
  double reference_lat = 0;  // and sideways against each actor's own lane, positive left
  double other_lat = 0;
  double heading_difference = 0;  // the other's heading minus the frame's, in (-pi, pi]

  double ahead() const { return dx >= 0 ? 1.0 : -1.0; }
  double side() const { return dy >= 0 ? 1.0 : -1.0; }
  // Sideways velocities towards each other (m/s), positive when closing.
  double reference_towards() const { return reference_lat * side(); }
  double other_towards() const { return -other_lat * side(); }
};

// `other` seen from `reference` at `sample`; both must be present there.
PairGeometry pair_geometry(const Trace& trace, const RoadMap& map, ActorId reference, ActorId other,
                           std::size_t sample);

// pair_geometry's parts, for a caller that needs only the gaps (behaviour coverage: the velocities
// cost two more lane lookups). The frame of `reference` at `sample`: the heading of the lane it
// follows, else its own.
double pair_frame_heading(const Trace& trace, const RoadMap& map, ActorId reference,
                          std::size_t sample);
// The gaps between the bodies along and across the frame `frame_heading` (pair_geometry's gap_lon
// and gap_lat, the same values).
struct BodyGaps {
  double lon = 0;
  double lat = 0;
};
BodyGaps body_gaps(const Trace& trace, ActorId reference, ActorId other, std::size_t sample,
                   double frame_heading);

// The angle a to (-pi, pi].
double wrap_angle(double a);

}  // namespace scenfuzz
