// Which parts of the map a trace's picture shows: the main view crops to the ego's path, its
// target and the bodies near the event (not every actor's whole path), the inset to the event
// and the 3 s before it; both with bounded aspect ratios, so that a long straight road makes
// neither a sliver nor a tower.
#pragma once

#include <optional>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"
#include "physics/trace/trace_moment.hpp"

namespace scenfuzz {

inline constexpr double kMainMaxAspect = 3;     // longer side over shorter, main view
inline constexpr double kInsetMaxAspect = 1.5;  // the inset
inline constexpr double kInsetLookBack = 3;     // s of bodies before the event in the inset

// `bounds` grown about its centre so that neither side is more than `max_aspect` times the
// other.
MapBounds with_bounded_aspect(const MapBounds& bounds, double max_aspect);

// The inset: the event, the ego and the other party then and up to kInsetLookBack before, and
// where they would be 1 s later at their speeds (the arrows' tips).
MapBounds inset_region(const Trace& trace, const TraceMoment& moment);

// The main view: everything the ego did, its target, the inset, and the other bodies' positions
// near the ego in the 5 s before the event. Without a moment, what the actors visited, or the
// whole map.
MapBounds main_region(const RoadMap& map, const Trace& trace,
                      const std::optional<TraceMoment>& moment,
                      const std::optional<MapBounds>& inset);

// The velocity of actor id at sample i (speed along the heading, against it while reversing).
MapPoint velocity_at(const TraceActor& actor, std::size_t i);

}  // namespace scenfuzz
