// The nearest point of a stretch of path to a point, if it lies within a reach: what a lane
// follower asks of its path for every actor it looks at. Boxes of runs of segments rule out most
// of the stretch without a projection, and segments are compared by squared distance first, so
// only the few near the point cost a square root.
#pragma once

#include <cstddef>

#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/polyline_boxes.hpp"
#include "physics/map/segment_frames.hpp"

namespace scenfuzz {

// Among the segments first, first + 1, ... of `path` that start at or before arc length `until`:
// the projection onto the nearest to `point` (SegmentFrames::project's, bit for bit; of equally
// near segments the first), when its distance is at most `reach`; otherwise a projection whose
// distance is infinite. `boxes` and `frames` are those of `path`.
PolylineProjection nearest_on_path(const Polyline& path, const PolylineBoxes& boxes,
                                   const SegmentFrames& frames, MapPoint point, std::size_t first,
                                   double until, double reach);

}  // namespace scenfuzz
