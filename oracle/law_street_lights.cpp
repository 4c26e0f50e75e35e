// Street lighting from the lane the ego is on and the time of day: off the lanes there is no
// street, and a lane without a speed limit says nothing of its road, so neither is lit.
#include "oracle/law_street_lights.hpp"

#include <cstddef>

#include "physics/ego/perception.hpp"

namespace scenfuzz {

namespace {

// Lamps switch on at dusk and off at dawn: whenever the perception model's darkness is above 0.
bool lamps_on(double time_of_day) { return darkness_at(time_of_day) > 0; }

bool lit_street(const RoadMap& map, std::int32_t lane) {
  if (lane < 0) return false;
  const double limit = map.lane(static_cast<LaneIndex>(lane)).speed_limit;
  return limit > 0 && limit <= kLitStreetSpeedLimit;
}

}  // namespace

std::vector<double> street_lights_on(const Trace& trace, const RoadMap& map,
                                     double start_time_of_day) {
  const TraceActor& ego = trace.actors[kEgo];
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] =
        lamps_on(start_time_of_day + trace.time[i]) && lit_street(map, ego.lane[i]) ? 1.0 : 0.0;
  return values;
}

}  // namespace scenfuzz
