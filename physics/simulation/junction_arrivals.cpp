// Junction arrival times (junction_arrivals.hpp).
#include "physics/simulation/junction_arrivals.hpp"

#include <cmath>
#include <limits>

namespace scenfuzz {

bool at_junction(const RoadMap& map, LaneFix fix) {
  if (fix.lane < 0) return false;
  const Lane& lane = map.lane(static_cast<LaneIndex>(fix.lane));
  if (lane.junction) return true;
  if (lane.length() - fix.s > kArrivalReach) return false;
  for (LaneIndex next : lane.successors)
    if (map.lane(next).junction) return true;
  return false;
}

void JunctionArrivals::update(const RoadMap& map, double t, std::span<const LaneFix> fixes,
                              std::span<const TraceActorKind> kinds,
                              std::span<const std::uint8_t> present) {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  arrivals_.resize(fixes.size(), kNone);
  for (std::size_t k = 0; k < fixes.size(); ++k) {
    const bool vehicle = kinds[k] == TraceActorKind::vehicle || kinds[k] == TraceActorKind::ego;
    const bool here = present.empty() || present[k] != 0;
    if (!vehicle || !here || !at_junction(map, fixes[k]))
      arrivals_[k] = kNone;
    else if (std::isnan(arrivals_[k]))
      arrivals_[k] = t;
  }
}

}  // namespace scenfuzz
