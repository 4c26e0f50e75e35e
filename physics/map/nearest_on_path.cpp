// The nearest point of a stretch of path within a reach (see nearest_on_path.hpp).
#include "physics/map/nearest_on_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// m added to a bound before a box rules its segments out: far above the rounding of a distance
// between map points (about 1e-9 m at UTM coordinates), far below anything that matters.
constexpr double kRoundingMargin = 1e-6;

}  // namespace

PolylineProjection nearest_on_path(const Polyline& path, const PolylineBoxes& boxes,
                                   const SegmentFrames& frames, MapPoint point, std::size_t first,
                                   double until, double reach, double known) {
  const auto& arc = path.arc_lengths();
  const std::size_t count = path.segment_count();
  constexpr std::size_t run = PolylineBoxes::kRun;
  constexpr std::size_t group = PolylineBoxes::kGroup;
  std::size_t best = count;
  double best_squared = kInfinity, best_distance = kInfinity;
  // A box farther than this holds no segment within reach, nor one nearer than the best found
  // (or than the known segment: the nearest is no farther than that one).
  double bound = std::min(reach, known) + kRoundingMargin;
  double bound_squared = bound * bound;
  for (std::size_t box = first / run; box < boxes.size() && arc[box * run] <= until; ++box) {
    // At a group's first box (or the stretch's), the whole group may be out of the bound: its
    // box is no farther than any of its boxes, so each of them would be skipped below.
    if (box % group == 0 || box == first / run) {
      if (boxes.group_distance_squared(box / group, point) > bound_squared) {
        box = (box / group + 1) * group - 1;
        continue;
      }
    }
    if (boxes.distance_squared(box, point) > bound_squared) continue;
    const std::size_t end = std::min(box * run + run, count);
    for (std::size_t seg = std::max(first, box * run); seg < end && arc[seg] <= until; ++seg) {
      const double squared = frames.distance_squared(path, point, seg);
      // The root does not decrease as its argument grows: a larger square is no nearer.
      if (squared > best_squared) continue;
      const double distance = std::sqrt(squared);
      if (!(distance < best_distance)) continue;  // equally near: the first found stays
      best = seg;
      best_squared = squared;
      best_distance = distance;
      bound = std::min(reach, distance) + kRoundingMargin;
      bound_squared = bound * bound;
    }
  }
  if (best == count || best_distance > reach) {
    PolylineProjection none;
    none.distance = kInfinity;
    return none;
  }
  return frames.project(path, point, best);
}

bool surely_clear_of(const Polyline& path, const PolylineBoxes& boxes, MapPoint a, MapPoint b,
                     std::size_t first, double until, double reach) {
  constexpr double kMargin = 1e-3;  // m: far above the rounding of boxes and coordinates
  const double wide = reach + kMargin;
  const MapPoint low{std::min(a.x, b.x) - wide, std::min(a.y, b.y) - wide};
  const MapPoint high{std::max(a.x, b.x) + wide, std::max(a.y, b.y) + wide};
  const auto& arc = path.arc_lengths();
  constexpr std::size_t run = PolylineBoxes::kRun;
  // A point within reach of a segment has the segment's box within reach.
  for (std::size_t box = first / run; box < boxes.size() && arc[box * run] <= until; ++box) {
    const MapPoint box_low = boxes.low(box), box_high = boxes.high(box);
    if (box_low.x <= high.x && low.x <= box_high.x && box_low.y <= high.y && low.y <= box_high.y)
      return false;
  }
  return true;
}

}  // namespace scenfuzz
