// Axis-aligned bounding boxes of runs of a polyline's segments, for rejection tests that are
// exact: a point farther from a run's box than some distance is farther than that from every
// segment of the run, so none of them needs projecting to know it is out of reach.
#pragma once

#include <cstddef>
#include <vector>

#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

class PolylineBoxes {
 public:
  // Segments per box: runs of a few metres on paths sampled every metre or so.
  static constexpr std::size_t kRun = 8;

  PolylineBoxes() = default;
  explicit PolylineBoxes(const Polyline& path);

  // Whether `point` lies farther than `reach` from every segment `first`, first + 1, ... of
  // `path` that starts at or before arc length `until` (with room for rounding: true means every
  // projection onto those segments measures more than `reach`).
  bool all_beyond(const Polyline& path, MapPoint point, std::size_t first, double until,
                  double reach) const;

 private:
  struct Box {
    MapPoint low, high;
  };
  std::vector<Box> boxes_;  // box k holds segments k * kRun .. k * kRun + kRun - 1
};

}  // namespace scenfuzz
