// Axis-aligned bounding boxes of runs of a polyline's segments, for rejection tests that are
// exact: a point farther from a run's box than some distance is farther than that from every
// segment of the run, so none of them needs projecting to know it is out of reach. Groups of runs
// have boxes too (each the smallest holding its runs' boxes), so that a long stretch far from the
// point is ruled out a group at a time.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

class PolylineBoxes {
 public:
  // Segments per box: runs of a few metres on paths sampled every metre or so.
  static constexpr std::size_t kRun = 8;
  // Boxes per group: group g holds boxes g * kGroup ... g * kGroup + kGroup - 1.
  static constexpr std::size_t kGroup = 8;

  PolylineBoxes() = default;
  explicit PolylineBoxes(const Polyline& path);

  // Boxes for the segments before `segments` only (a multiple of kRun * kGroup, or the path's
  // segment count: every group complete), made as far as a caller reads: the boxes made are those
  // of PolylineBoxes(path), and size() counts only them.
  void extend(const Polyline& path, std::size_t segments);
  // The segments that have boxes.
  std::size_t segments() const { return segments_; }

  std::size_t size() const { return boxes_.size(); }
  MapPoint low(std::size_t box) const { return boxes_[box].low; }
  MapPoint high(std::size_t box) const { return boxes_[box].high; }

  // The squared distance from `point` to box `box` (0 inside it): at most the squared distance
  // to any of the segments box * kRun ... box * kRun + kRun - 1 (up to rounding, about 1e-12 of
  // the coordinates).
  double distance_squared(std::size_t box, MapPoint point) const {
    return box_distance_squared(boxes_[box], point);
  }

  // The squared distance from `point` to group `group`'s box: at most distance_squared(box,
  // point) of each of its boxes, exactly (the group's box holds theirs, and every operation on
  // the way is monotone under rounding), so a group farther than a bound has no box within it.
  double group_distance_squared(std::size_t group, MapPoint point) const {
    return box_distance_squared(groups_[group], point);
  }

 private:
  struct Box {
    MapPoint low, high;
  };
  static double box_distance_squared(const Box& b, MapPoint point) {
    const double dx = std::max(std::max(b.low.x - point.x, 0.0), point.x - b.high.x);
    const double dy = std::max(std::max(b.low.y - point.y, 0.0), point.y - b.high.y);
    return dx * dx + dy * dy;
  }
  std::vector<Box> boxes_;   // box k holds segments k * kRun .. k * kRun + kRun - 1
  std::vector<Box> groups_;  // group g holds boxes g * kGroup .. g * kGroup + kGroup - 1
  std::size_t segments_ = 0;
};

}  // namespace scenfuzz
