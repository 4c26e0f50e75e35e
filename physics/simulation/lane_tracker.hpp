// Which lane an actor is on, step after step, for the trace's lane and s columns. Asking the
// map's spatial index every step for every actor would dominate a step; an actor is almost always
// still on the lane it was on, so that lane is checked first, near where the actor was.
#pragma once

#include <cstdint>
#include <utility>

#include "physics/map/lane_queries.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

struct LaneFix {
  std::int32_t lane = -1;  // -1: on no lane
  double s = 0;
};

class LaneTracker {
 public:
  // RoadMap::widest_half_lane() of the map the actor is on.
  explicit LaneTracker(double widest_half_lane) : widest_half_lane_(widest_half_lane) {}

  LaneFix update(const RoadMap& map, MapPoint point, double heading);
  // The actor is at `fix`, known otherwise (a lane follower's route): the next update starts
  // looking there.
  void assume(LaneFix fix) {
    lane_ = fix.lane;
    assumed_s_ = fix.s;
    segment_known_ = false;
    off_lanes_ = false;
  }

 private:
  double widest_half_lane_;
  std::int32_t lane_ = -1;
  std::size_t segment_ = 0;
  bool segment_known_ = true;  // else segment_ is the one at assumed_s_ on lane_
  double assumed_s_ = 0;
  bool off_lanes_ = false;
  MapPoint off_lanes_at_;       // where the map last said: on no lane
  double off_lanes_reach_ = 0;  // how far from there no lane can begin
};

}  // namespace scenfuzz
