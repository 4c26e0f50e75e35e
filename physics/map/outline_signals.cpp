// add_signals (outline_signals.hpp): one light per road of a junction, its stop lines across the
// ends of the road's lanes coming in, the two roads' plans half a cycle apart.
#include "physics/map/outline_signals.hpp"

#include <cstddef>

#include "physics/map/plane_vectors.hpp"
#include "physics/map/signal_plans.hpp"

namespace scenfuzz::outline {

namespace {

using namespace plane;

// Where in its cycle a plan starts showing `colour`.
double phase_start(const SignalPlan& plan, SignalColour colour) {
  double start = 0;
  for (const SignalPhase& phase : plan.phases) {
    if (phase.colour == colour) return start;
    start += phase.duration;
  }
  return 0;
}

// The road's light: a stop line across the ends of each arm's lanes coming in, from the kerb to
// the centre line, and a head at its kerb end.
TrafficLightDescription light_of(const MapDescription& map, const std::string& id,
                                 const std::string& road, const std::vector<JunctionArm>& arms) {
  TrafficLightDescription light;
  light.id = id;
  for (const JunctionArm& arm : arms) {
    if (arm.road != road || arm.in_lanes.empty()) continue;
    const LaneDescription& kerb = lane_named(map, arm.in_lanes.back());
    const LaneDescription& inner = lane_named(map, arm.in_lanes.front());
    light.stop_lines.push_back({kerb.right_boundary.back(), inner.left_boundary.back()});
    light.heads.push_back(kerb.right_boundary.back());
    for (const std::string& id_in : arm.in_lanes) {
      const double end = length_of(lane_named(map, id_in).centre_line);
      light.lanes.push_back({id_in, end, end});
    }
  }
  return light;
}

}  // namespace

void add_signals(MapDescription& map, const std::string& light, const std::string& road,
                 SignalColour colour, const std::vector<JunctionArm>& arms) {
  std::vector<std::string> roads{road};
  for (const JunctionArm& arm : arms)
    if (arm.road != road && (roads.size() < 2 || roads[1] != arm.road)) roads.push_back(arm.road);
  SCENFUZZ_DEMAND(roads.size() == 2);
  const SignalPlan first = two_direction_plan(kDefaultGreen, kDefaultYellow, kDefaultAllRed, false);
  const double start = phase_start(first, colour);
  for (std::size_t r = 0; r < roads.size(); ++r) {
    TrafficLightDescription signal = light_of(map, light + "_" + roads[r], roads[r], arms);
    signal.plan = two_direction_plan(kDefaultGreen, kDefaultYellow, kDefaultAllRed, r == 1);
    signal.plan->offset += start;
    map.traffic_lights.push_back(std::move(signal));
  }
}

}  // namespace scenfuzz::outline
