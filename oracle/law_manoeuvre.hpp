// The ego's manoeuvres as the law signals read them from a simulated run: the lanes it drives on
// (the trace's lane column), when it changes lane, which way it turns at the next junction
// (scenest's `direction`, `isLaneChanging`, `isTurningAround`, `currentLane.direction`), and
// when it overtakes (`isOverTaking`).
// LawBreaker takes them from Apollo's planner; our drivers record no intent, so the lanes the
// ego actually takes stand for it. Private to the oracle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lang/scenario.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// LawBreaker's codes for `direction` (Apollo's turn-signal codes).
inline constexpr double kForward = 0, kLeft = 1, kRight = 2;

// The lanes the ego drives on, in order, with the samples it spends on each; samples off the
// lanes belong to no visit.
struct LaneVisits {
  std::vector<LaneIndex> lanes;
  std::vector<std::size_t> first_sample, last_sample;  // per visit
  std::vector<std::optional<std::size_t>> visit_at;    // per sample: index into lanes
};

LaneVisits lane_visits(const TraceActor& actor);

struct EgoManoeuvre {
  std::vector<double> direction;            // per sample: kForward, kLeft or kRight
  std::vector<std::uint8_t> lane_changing;  // per sample
};

// Where the scenario sends the ego: its target state on the lanes; nullopt without a target or
// where it cannot be placed.
std::optional<LanePosition> ego_target(const ScenarioTemplate& scenario,
                                       std::span<const double> parameters, const Trace& trace,
                                       const RoadMap& map);

// `direction` and `isLaneChanging` at every sample (docs/oracle.md gives the rules). Past the
// end of the run the ego's way ahead is its route to `target`.
EgoManoeuvre ego_manoeuvre(const Trace& trace, const RoadMap& map,
                           const std::optional<LanePosition>& target);

// `isTurningAround`: 1 where the ego signals a turn and its heading turns by more than 135
// degrees within the next kTurnAroundWindow seconds, else 0.
inline constexpr double kTurnAroundWindow = 8;  // s
std::vector<double> turning_around(const Trace& trace, const EgoManoeuvre& manoeuvre);

// `isOverTaking`: 1 while the ego overtakes a vehicle that drives its way: the ego changes lane
// out of the lane that vehicle is ahead of it in (or out of one the vehicle's lane follows),
// passes it beside it within kOvertakeBeside of its centre line, from the lane change out until
// the vehicle is behind, and on through the lane change back after (docs/oracle.md), else 0.
// Passing a vehicle in the next lane without leaving its own lane for it is no overtaking.
inline constexpr double kOvertakeBeside = 5;  // m: centre to centre, across the ego's heading
std::vector<double> overtaking(const Trace& trace, const RoadMap& map,
                               const EgoManoeuvre& manoeuvre);

// `currentLane.direction` at every sample: the manoeuvres the ego's lane allows, in LawBreaker's
// 0-7 coding; 0 off the lanes.
std::vector<double> current_lane_direction(const Trace& trace, const RoadMap& map);

}  // namespace scenfuzz
