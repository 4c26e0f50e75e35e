// What a simulation produces: one sample per step for every actor, in columns (structure of
// arrays, so the oracle scans one signal at a time), the ego's perception of every other actor,
// the traffic lights' colours, and the events of the run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/actors/vehicle_signals.hpp"
#include "physics/collision/body_side.hpp"
#include "physics/map/map_description.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

// Index into Trace::actors. The ego is always actor 0.
using ActorId = std::uint32_t;
inline constexpr ActorId kEgo = 0;

enum class TraceActorKind { ego, vehicle, pedestrian, obstacle };

// An obstacle's body as the scenario gives it; actors are boxes (vehicles) or cylinders.
enum class BodyShape { box, cylinder, sphere, cone };

struct TraceActor {
  std::string name;  // as the scenario's specs refer to it ("ego", "npc1", "ped", "obs1")
  TraceActorKind kind = TraceActorKind::vehicle;
  ActorCategory category = ActorCategory::car;  // obstacles: unused
  BodyShape shape = BodyShape::box;
  double length = 0;  // box: along the heading; round shapes: diameter
  double width = 0;   // box: across; round shapes: diameter
  double height = 0;

  // One entry per sample. `speed` is a magnitude and `acceleration` how fast it grows: the
  // velocity is `speed` along `heading`, or against it where `reversing` is 1.
  std::vector<double> x, y, heading, speed, acceleration, yaw_rate;
  std::vector<std::int32_t> lane;       // LaneIndex of the lane the centre is on, -1 on none
  std::vector<double> s;                // arc length on `lane`; 0 when lane is -1
  std::vector<std::uint8_t> reversing;  // one per sample, or empty: it never reverses
  std::vector<VehicleSignals> signals;  // one per sample, or empty: it never shows any

  // The samples [present_from, present_until) in which the actor is on the map. Scenario actors
  // are present throughout (the defaults); a background-traffic vehicle (a Flow's) enters the map
  // at its spawn and leaves it at the end of its route, and one that never got in has an empty
  // interval. Outside it the columns still hold finite values (the entry pose before, the exit
  // pose after, at rest, lane -1), but nothing may read them as the actor being there: it is not
  // in the collision world, not perceived, not audited, not drawn, not exported as CSV rows.
  std::size_t present_from = 0;
  std::size_t present_until = std::numeric_limits<std::size_t>::max();
};

// Whether the actor is on the map at sample i.
inline bool present_at(const TraceActor& actor, std::size_t i) {
  return i >= actor.present_from && i < actor.present_until;
}

// Whether the actor is on the map throughout a run of `sample_count` samples.
inline bool present_throughout(const TraceActor& actor, std::size_t sample_count) {
  return actor.present_from == 0 && actor.present_until >= sample_count;
}

// Whether `reversing` (a TraceActor's or PerceivedActor's column) says sample i moved backwards.
inline bool reversing_at(const std::vector<std::uint8_t>& reversing, std::size_t i) {
  return !reversing.empty() && reversing[i] != 0;
}

// The velocity along the heading at sample i: the speed, negative while reversing.
inline double longitudinal_velocity_at(const std::vector<double>& speed,
                                       const std::vector<std::uint8_t>& reversing, std::size_t i) {
  return reversing_at(reversing, i) ? -speed[i] : speed[i];
}

// How the ego saw one other actor at each sample (after range, field of view, misses, noise and
// latency). Samples where it was not detected have detected == 0 and NaN elsewhere (reversing
// 0).
struct PerceivedActor {
  ActorId actor = 0;
  std::vector<std::uint8_t> detected;
  std::vector<double> x, y, heading, speed;
  std::vector<std::uint8_t> reversing;  // as TraceActor's: one per sample, or empty
};

struct TraceLight {
  std::string id;                    // the map's traffic light id
  std::vector<SignalColour> colour;  // one per sample
};

struct Collision {
  double time = 0;
  ActorId first = 0;  // the lower actor id of the pair
  ActorId second = 0;
  MapPoint point;  // a contact point, map frame
  BodySide first_side = BodySide::front;
  BodySide second_side = BodySide::front;
};

enum class TraceEventKind {
  collision,       // detail: the index into Trace::collisions
  target_reached,  // the ego reached its target state
  timeout,         // the scenario's duration elapsed
  ego_failure,     // the ego driver (a plugin) crashed, hung or returned an error
  end_condition,   // one of the scenario's end conditions held (WMG SDL `END:`)
};

struct TraceEvent {
  TraceEventKind kind = TraceEventKind::timeout;
  double time = 0;
  std::int64_t collision = -1;  // collision events: index into Trace::collisions
  std::string message;          // ego_failure: what happened
};

enum class EndReason { duration, target_reached, collision, ego_failure, end_condition };

// How the ego under test (a plugin) failed: each kind is a finding of its own.
enum class EgoFailureKind {
  crash,  // the plugin's process died: a signal, or an exit
  hang,   // it did not answer within its time limit (step or start)
  error,  // it could not be loaded or created, returned non-zero or a non-finite control
};

struct EgoFailure {
  EgoFailureKind kind = EgoFailureKind::error;
  std::string reason;            // the whole message, naming the library and the step
  std::string signal;            // a crash by a signal: its name ("SIGSEGV"); empty otherwise
  long step = 0;                 // the plugin step that failed, from 1; 0: while starting
  double time = 0;               // simulated s at the failure
  std::string last_observation;  // the last observation handed to the plugin (JSON); empty at 0
};

// How far the ego's perception reached in this run (perception.hpp's settings degraded by the
// scenario's weather and darkness, which hold for the whole run).
struct TraceSensing {
  double vehicle_range = 0;     // m; 0: not recorded
  double pedestrian_range = 0;  // m
  bool limited = false;         // shorter than in clear daylight, by weather or darkness
};

struct Trace {
  std::string map_name;
  std::uint64_t seed = 0;
  double dt = 0.05;
  std::vector<double> time;  // time[i] = i * dt
  std::vector<TraceActor> actors;
  std::vector<PerceivedActor> perceived;  // one per actor other than the ego, in actor order
  std::vector<TraceLight> lights;
  std::vector<Collision> collisions;
  std::vector<TraceEvent> events;  // in time order
  EndReason end = EndReason::duration;
  std::optional<EgoFailure> ego_failure;  // set exactly when end is EndReason::ego_failure
  std::optional<MapPoint> ego_target;     // where the ego was to go, when it had a target
  TraceSensing sensing;

  std::size_t sample_count() const { return time.size(); }
  // The actor named `name`, or nullopt.
  std::optional<ActorId> find_actor(const std::string& name) const;
};

std::string_view trace_actor_kind_name(TraceActorKind kind);
std::string_view end_reason_name(EndReason reason);
// "ego_crash", "ego_hang", "ego_error": the finding kinds.
std::string_view ego_failure_kind_name(EgoFailureKind kind);
std::string_view signal_colour_name(SignalColour colour);

}  // namespace scenfuzz
