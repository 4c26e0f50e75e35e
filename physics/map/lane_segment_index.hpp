// A spatial index over every segment of every lane centre line, for point-to-lane projection and
// area queries. Boost.Geometry's R-tree does the work; it stays out of this header so that only
// lane_segment_index.cpp pays for compiling it.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {

struct Lane;

struct LaneSegmentReference {
  std::uint32_t lane = 0;
  std::uint32_t segment = 0;  // index of the segment in the lane's centre line
};

class LaneSegmentIndex {
 public:
  explicit LaneSegmentIndex(const std::vector<Lane>& lanes);
  ~LaneSegmentIndex();
  LaneSegmentIndex(const LaneSegmentIndex&) = delete;
  LaneSegmentIndex& operator=(const LaneSegmentIndex&) = delete;

  // The segment nearest to `point`; false when the index is empty.
  bool nearest(MapPoint point, LaneSegmentReference& result) const;
  // Segments whose bounding boxes meet the box [min, max].
  std::vector<LaneSegmentReference> segments_in_box(MapPoint min, MapPoint max) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace scenfuzz
