// The moment a picture of a trace zooms on: the ego's first collision; without one, the time the
// spec's verdict names; without that, the ego's nearest approach to another body. With it, the
// other party: the body hit, or the nearest one then.
#pragma once

#include <cstddef>
#include <optional>

#include "physics/map/map_point.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

enum class MomentKind { collision, verdict, nearest_approach, end };

struct TraceMoment {
  MomentKind kind = MomentKind::end;
  std::size_t sample = 0;
  double time = 0;
  MapPoint point;                        // the contact point, or the ego's position
  std::optional<ActorId> other;          // the other party, if any other body is on the map
  std::optional<std::size_t> collision;  // kind collision: the index into Trace::collisions
};

// nullopt for a trace without samples or whose ego is never at a finite position.
std::optional<TraceMoment> key_moment(const Trace& trace, std::optional<double> verdict_time);

// The sample at or just after `time`, within the trace.
std::size_t sample_at(const Trace& trace, double time);

// Whether actor `id` is drawn at sample i: on the map then at a finite position.
bool drawn_at(const Trace& trace, std::size_t id, std::size_t i);

// The gap between the ego's body and actor id's at sample i; +inf when either is not drawn.
double gap_to_ego(const Trace& trace, ActorId id, std::size_t i);

// The body nearest the ego's at sample i (by the gap between their footprints), if any.
std::optional<ActorId> nearest_to_ego(const Trace& trace, std::size_t i);

}  // namespace scenfuzz
