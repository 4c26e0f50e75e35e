// Failure modes: what makes two findings "the same failure". As libFuzzer and ClusterFuzz dedupe
// crashes by their crash state (the top frames), a mode is keyed by what identifies a failure to
// a user and stays the same from run to run of it: the violated atom, the kind of event
// (collision, near miss, stuck, rule), the other road user's role, whose fault a collision was,
// and the ego's coarse manoeuvre phase (ego_phase.hpp). What flickers between runs of one failure
// (the touching sides, where the other was at contact, the fine activity label, the road feature,
// the other's class within a flow) describes the finding but is not in the key. The search writes
// one representative finding per key and counts the rest (docs/search.md, "Findings and failure
// modes").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "oracle/ego_phase.hpp"
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

// What happened, the first that applies: the ego touched another road user; the spec was
// violated only because the run ended while the ego was stuck (judge.hpp); the violated atom
// compares the distance between two road users (SpecVerdict::actor_distance, so that all
// violations of one distance atom are one kind, whatever its threshold); else a rule was broken.
enum class FailureEvent { collision, stuck, near_miss, rule };

// Where the other road user's centre was in the ego's frame just before contact: past the ego's
// front bumper line, behind its rear one, or between them. Which corners touched flickers from
// run to run of one crash; this does less, but still does for a car cutting in level with a bumper
// (ahead in one run, beside in the next), so it describes a finding and is not in the key.
enum class ContactDirection { ahead, beside, behind };

struct FailureMode {
  // The key's fields (failure_mode_key).
  std::string atom;  // the violated atom as written, or "collision"
  FailureEvent event = FailureEvent::rule;
  std::string other_role;      // its name; a background-traffic vehicle by its flow's name
  std::string responsibility;  // "ego", "other", "shared"; empty: no collision
  EgoPhase phase = EgoPhase::in_lane;
  // The description of this finding (failure_mode_details), not the key.
  std::optional<ContactDirection> direction;  // a collision's
  std::string other_class;  // "car", "pedestrian", "obstacle", ...; empty: no other actor
  EgoActivity ego_activity = EgoActivity::cruising;
  RoadFeature road_feature = RoadFeature::straight;
  std::optional<BodySide> ego_side, other_side;  // a collision's touching sides
};

std::string_view ego_activity_name(EgoActivity activity);
std::string_view road_feature_name(RoadFeature feature);
std::string_view failure_event_name(FailureEvent event);
std::string_view contact_direction_name(ContactDirection direction);

// The mode as one line, `atom | event | other | responsibility | phase`, the other as its role,
// "-" for none and for a rule event (the key findings are grouped by; docs/search.md documents it).
std::string failure_mode_key(const FailureMode& mode);
// The rest of what was seen, for a finding's header: "car lead ahead; ego pulling out on a
// straight; touching ego front, lead rear".
std::string failure_mode_details(const FailureMode& mode);

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
// actor: the one the ego first collided with, if it collided, with the touching sides and its
// direction; else at the verdict's time the road user it was following (EgoActivity::following),
// else the nearest (vehicle or pedestrian, centre to centre, within kNearbyActor). The ego's
// activity and road feature: at the collision, else at that time; its phase there too, or at
// `phase_sample` when given (CollisionResponsibility::danger_began: when the danger began).
inline constexpr double kNearbyActor = 50;  // m
FailureMode describe_failure(const Trace& trace, const RoadMap& map, const SpecVerdict& verdict,
                             std::optional<std::size_t> phase_sample = std::nullopt);

// The violated verdicts' indices, the earliest in time first (ties in file order): a finding
// names them in this order and its mode is the first's, so a crash is never reported as the
// target a later conjunct missed.
std::vector<std::size_t> violation_order(const std::vector<SpecVerdict>& verdicts);

// The sample nearest `time` (clamped to the trace).
std::size_t sample_at_time(const Trace& trace, double time);

}  // namespace scenfuzz
