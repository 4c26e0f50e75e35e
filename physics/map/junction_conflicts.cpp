// Junction lane conflicts found once per lane (junction_conflicts.hpp).
#include "physics/map/junction_conflicts.hpp"

#include "physics/map/lane_conflicts.hpp"

namespace scenfuzz {

const std::vector<LaneIndex>& JunctionConflicts::of(LaneIndex lane) const {
  if (known_.size() < map_->lanes().size()) known_.resize(map_->lanes().size());
  std::optional<std::vector<LaneIndex>>& known = known_[lane];
  if (!known) known = conflicting_lanes(*map_, lane);
  return *known;
}

}  // namespace scenfuzz
