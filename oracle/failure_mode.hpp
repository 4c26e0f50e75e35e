// Failure modes: what makes two findings "the same failure". A signature names the violated
// atom, the other road user involved (class and role), whose fault a collision was, what the ego
// was doing and where (the road feature), and the sides that touched. The search writes one
// representative finding per signature and counts the rest (docs/search.md, "Failure modes").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "oracle/judge.hpp"
#include "physics/collision/body_side.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// What the ego was doing at a moment, read from its trace: the first that applies, in this order.
enum class EgoActivity {
  reversing,
  stopped,        // slower than kEgoStoppedSpeed
  pulling_out,    // moving again within kPullOutWindow of being stopped
  changing_lane,  // on a forward neighbour lane of the lane it is on within kLaneChangeWindow
  turning_left,   // on a junction lane that turns left (right, back)
  turning_right,
  turning_around,
  following,  // another road user ahead in its lane, within max(10 m, 3 s at its speed)
  cruising,
};

// Where the ego was: the first that applies, in this order (a merge: on or beside an ending
// acceleration lane, or on or just before a lane two lanes run into). `straight` is a plain stretch
// of road (straight or curved) with none of the others near.
enum class RoadFeature { roundabout, crosswalk, junction, merge, straight };

inline constexpr double kEgoStoppedSpeed = 0.3;  // m/s
inline constexpr double kPullOutWindow = 3;      // s
inline constexpr double kLaneChangeWindow = 2;   // s either side
inline constexpr double kCrosswalkMargin = 3;    // m around a crosswalk's outline
inline constexpr double kJunctionMargin = 5;     // m around a junction's outline
inline constexpr double kMergeLookahead = 30;    // m before a lane that merges into another

struct FailureMode {
  std::string atom;            // the violated atom as written, or "collision"
  std::string other_class;     // "car", "pedestrian", "obstacle", ...; empty: no other actor
  std::string other_role;      // its name; a background-traffic vehicle by its flow's name
  std::string responsibility;  // "ego", "other", "shared"; empty: no collision judged
  EgoActivity ego_activity = EgoActivity::cruising;
  RoadFeature road_feature = RoadFeature::straight;
  std::optional<BodySide> ego_side, other_side;  // a collision's touching sides
};

std::string_view ego_activity_name(EgoActivity activity);
std::string_view road_feature_name(RoadFeature feature);

// The mode as one line, fields separated by " | " (the key findings are grouped by).
std::string failure_mode_key(const FailureMode& mode);

// A background-traffic vehicle is named "<flow>.<n>", numbered in spawn order, which depends on
// the seed; its role is the flow. Scenario actors (whose names have no dot) are their name.
std::string actor_role(const TraceActor& actor);
// "car", "bicycle", ..., "pedestrian" or "obstacle".
std::string actor_class_name(const TraceActor& actor);

EgoActivity ego_activity_at(const Trace& trace, const RoadMap& map, std::size_t sample);
RoadFeature road_feature_at(const Trace& trace, const RoadMap& map, std::size_t sample);

// What road_feature_at learns about the map (whether each lane is an acceleration lane, which
// projects its end on every neighbour: costly on long curved lanes; the bounding boxes of the
// crosswalks and junctions, which a city map has hundreds of), kept over one pass over a trace so
// that it is worked out once instead of at every sample. Empty: nothing known.
struct RoadFeatureMemo {
  struct Box {
    double low_x = 0, low_y = 0, high_x = 0, high_y = 0;
    bool empty = true;  // an outline without points
  };
  std::vector<signed char> acceleration_lane;  // by lane: -1 not known yet, else 0 or 1
  std::vector<Box> crosswalks, junctions;      // by index in the map; built on first use
  bool boxed = false;
};
// road_feature_at with `memo`, which must only ever be used with `map`. The same answer.
RoadFeature road_feature_at(const Trace& trace, const RoadMap& map, std::size_t sample,
                            RoadFeatureMemo& memo);

// The failure mode of a violated verdict, responsibility left empty for the caller. The other
// actor: the one the ego first collided with, if it collided, with the touching sides; else the
// nearest road user (vehicle or pedestrian, centre to centre, within kNearbyActor) at the
// verdict's time. The ego's activity and road feature: at the collision, else at that time.
inline constexpr double kNearbyActor = 50;  // m
FailureMode describe_failure(const Trace& trace, const RoadMap& map, const SpecVerdict& verdict);

// The violated verdicts' indices, the earliest in time first (ties in file order): a finding
// names them in this order and its mode is the first's, so a crash is never reported as the
// target a later conjunct missed.
std::vector<std::size_t> violation_order(const std::vector<SpecVerdict>& verdicts);

// The sample nearest `time` (clamped to the trace).
std::size_t sample_at_time(const Trace& trace, double time);

}  // namespace scenfuzz
