// The nearest point of a stretch of path to a point, if it lies within a reach: what a lane
// follower asks of its path for every actor it looks at. Boxes of runs of segments rule out most
// of the stretch without a projection, and segments are compared by squared distance first, so
// only the few near the point cost a square root.
#pragma once

#include <cstddef>
#include <limits>

#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/polyline_boxes.hpp"
#include "physics/map/segment_frames.hpp"

namespace scenfuzz {

// Among the segments first, first + 1, ... of `path` that start at or before arc length `until`:
// the projection onto the nearest to `point` (SegmentFrames::project's, bit for bit; of equally
// near segments the first), when its distance is at most `reach`; otherwise a projection whose
// distance is infinite. `boxes` and `frames` are those of `path`.
//
// `known`, when finite, must be a distance from `point` to some segment of that stretch (or more):
// a caller that knows where the point was last (a segment near it) passes that segment's
// distance, and boxes farther than it are skipped from the start. The answer is the same.
PolylineProjection nearest_on_path(const Polyline& path, const PolylineBoxes& boxes,
                                   const SegmentFrames& frames, MapPoint point, std::size_t first,
                                   double until, double reach,
                                   double known = std::numeric_limits<double>::infinity());

// Whether every point of the line from `a` to `b` is surely farther than `reach` from each
// segment that nearest_on_path(path, boxes, ..., first, until, reach) may search (first, first +
// 1, ... starting by `until`, among those `boxes` are made for): the box of the two points, widened
// by the reach, meets none of those segments' boxes. Then no such search for a point on the line
// finds anything, and a caller looking for something moving from `a` to `b` need not search. By
// box tests only; false when it may be in reach.
bool surely_clear_of(const Polyline& path, const PolylineBoxes& boxes, MapPoint a, MapPoint b,
                     std::size_t first, double until, double reach);

}  // namespace scenfuzz
