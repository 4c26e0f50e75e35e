// Whether the ego was still making progress when its run ended at its duration: what tells a
// time-out (the run was too short to tell whether an `F` would hold) from a stuck ego (it would
// not have got there however long the run; docs/oracle.md, "Time-outs").
//
// The ego is stuck when, over the last kStuckWindow seconds of the run (all of it, if shorter),
// it drove less than kStuckDistance metres (path length) and no red or yellow light was ahead of
// it (trafficLightAhead.color, looking kNoRoadObjectAhead metres along its lanes) at any sample
// of that stretch: waiting at a light, or in its queue, is progress of a kind; standing still
// behind a parked car, at a crossing that never clears or off the road is not.
#pragma once

#include <span>
#include <string>

#include "lang/scenario.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

inline constexpr double kStuckWindow = 10;   // s
inline constexpr double kStuckDistance = 1;  // m

struct EgoProgress {
  bool stuck = false;
  // In words: "drove 0.2 m in the last 10 s with no red light ahead" or "drove 86 m in the
  // last 10 s".
  std::string description;
};

// The ego's progress over the end of `trace`, the run of `scenario` at `parameters` on `map`.
EgoProgress ego_progress_at_end(const Trace& trace, const ScenarioTemplate& scenario,
                                std::span<const double> parameters, const RoadMap& map);

}  // namespace scenfuzz
