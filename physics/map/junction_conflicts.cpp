// Junction lane conflicts found once per lane and map (junction_conflicts.hpp).
#include "physics/map/junction_conflicts.hpp"

#include "lang/demand.hpp"
#include "physics/map/lane_conflicts.hpp"

namespace scenfuzz {

JunctionConflicts::JunctionConflicts(std::size_t lanes)
    : known_(std::make_unique<Known[]>(lanes)), lanes_(lanes) {}

const std::vector<LaneIndex>& JunctionConflicts::of(const RoadMap& map, LaneIndex lane) const {
  SCENFUZZ_DEMAND(lane < lanes_ && map.lanes().size() == lanes_);
  Known& known = known_[lane];
  std::call_once(known.once, [&] { known.lanes = conflicting_lanes(map, lane); });
  return known.lanes;
}

const std::vector<ConflictPoint>& JunctionConflicts::points_of(const RoadMap& map,
                                                               LaneIndex lane) const {
  const std::vector<LaneIndex>& lanes = of(map, lane);
  Known& known = known_[lane];
  std::call_once(known.points_once, [&] {
    const LaneIndex own[] = {lane};
    known.points = conflict_points(map, own, lanes);
  });
  return known.points;
}

}  // namespace scenfuzz
