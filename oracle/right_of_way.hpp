// What RSS leaves to the map: the traffic lights and signs an actor drove past, and whether it
// obeyed them (crossed a stop line on red, passed a stop sign without stopping), read from the
// lanes and arc lengths the trace records. Private to the responsibility oracle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// A stop line of a light or a sign that an actor crossed between two samples.
struct CrossedControl {
  FeatureKind kind = FeatureKind::traffic_light;  // traffic_light, stop_sign or yield_sign
  std::uint32_t index = 0;                    // into RoadMap::traffic_lights() or signs(), by kind
  std::size_t sample = 0;                     // the first sample past the line
  SignalColour colour = SignalColour::green;  // lights: the colour there
  bool stopped = false;  // signs: the actor stood still in the seconds before the line
};

// Speed below which an actor counts as standing still (m/s).
inline constexpr double kStandstillSpeed = 0.1;

// The lights' and signs' stop lines `actor` crossed at samples (first, last], in time order.
// A lane change crosses none; a lane with no recorded lane (-1) is skipped over.
std::vector<CrossedControl> controls_crossed(const Trace& trace, const RoadMap& map, ActorId actor,
                                             std::size_t first, std::size_t last);

// The light's or sign's id in the map.
const std::string& control_id(const RoadMap& map, const CrossedControl& control);

// Whether crossing `control` broke the law: a red light, or a stop sign without stopping.
bool control_violated(const CrossedControl& control);

// The colour of light `index` (into RoadMap::traffic_lights()) at `sample`; green when the trace
// has no colours for it (nothing can be said to be red).
SignalColour light_colour(const Trace& trace, const RoadMap& map, std::uint32_t index,
                          std::size_t sample);

// A red light or a stop sign on the lane `actor` is on at `sample`, within `ahead` metres before
// its stop line; for "stopped at a red light".
struct ControlAhead {
  bool red_light = false;
  bool stop_sign = false;
};
ControlAhead control_ahead(const Trace& trace, const RoadMap& map, ActorId actor,
                           std::size_t sample, double ahead);

}  // namespace scenfuzz
