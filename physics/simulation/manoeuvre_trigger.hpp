// WMG SDL's WHEN, WHILE and END conditions evaluated in the simulation, one instant at a time
// (docs/wmg-semantics.md, "Conditions"). A Formula is compiled once, before the run, into a
// TriggerCondition whose names are resolved (actors to ids, lanes to lane indices, lights to map
// indices, words to values) and whose parameters are evaluated, so that a step only reads numbers.
// Physics keeps its own small evaluator rather than the oracle's: the oracle works on whole
// traces and physics may not depend on it.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/spec.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/world_snapshot.hpp"

namespace scenfuzz {

enum class TriggerSignal {
  number,               // `number`
  speed,                // speed(actor), m/s
  lane,                 // lane(actor): a lane index, -1 on no lane
  manoeuvre,            // manoeuvre(actor): an ObservedManoeuvre
  light,                // light(index): a SignalColour
  timer,                // timer(T): time + `number` (the timer's initial value)
  local_timer,          // timer(T, actor): `number` + the time since actor's first phase began
  lateral_offset,       // lateral_offset(actor, other): m, left of other positive
  longitudinal_offset,  // longitudinal_offset(actor, other): m, ahead of other positive
  collision,            // collision(): 1 once any collision has happened, else 0
  element,              // element(actor): index of the junction its lane lies in, -1 outside
  relative_location,    // relative_location(actor, other): the RelativeSector of actor from other
  relative_heading,     // relative_heading(actor, other): degrees, counter-clockwise
  add,
  subtract,
  multiply,
  divide,
  negate,
};

struct TriggerQuantity {
  TriggerSignal signal = TriggerSignal::number;
  double number = 0;
  std::uint32_t actor = 0;                // actor id; light index for `light`
  std::uint32_t other = 0;                // the second actor of the offsets
  std::vector<TriggerQuantity> operands;  // arithmetic
};

enum class TriggerKind { comparison, truth, negation, conjunction, disjunction, implication };

struct TriggerCondition {
  TriggerKind kind = TriggerKind::truth;
  CompareOp compare = CompareOp::equal;
  std::vector<TriggerQuantity> sides;  // comparison: two; truth: one (holds when non-zero)
  std::vector<TriggerCondition> operands;
};

// What the names in a condition can refer to.
struct TriggerNames {
  const RoadMap& map;
  std::span<const std::string> actors;  // by actor id
  std::span<const std::string> timers;
  std::span<const double> timer_initial_values;
  std::span<const double> values;  // the search parameters, for numbers that read them
};

// nullopt after reporting, at its place in the file, what cannot be evaluated: an unknown
// signal, actor, lane, light, timer or word, a temporal operator, an order comparison of words.
std::optional<TriggerCondition> compile_trigger(const Formula& formula, const TriggerNames& names,
                                                Diagnostics& diagnostics);

bool trigger_holds(const TriggerCondition& condition, const WorldSnapshot& world);

// lateral_offset and longitudinal_offset: where actor a's centre lies in the frame of actor b
// (along b's heading, and to its left).
double lateral_offset(const KinematicState& a, const KinematicState& b);
double longitudinal_offset(const KinematicState& a, const KinematicState& b);

// WMG SDL's eight sectors around an actor.
enum class RelativeSector { F, FSR, SR, RSR, R, RSL, SL, FSL };
// The sector actor a (body length a_length) is in as seen from b (b_length): beside b while the
// two overlap along b's heading, in front or behind otherwise; on b's left or right when a's
// centre is more than half a lane (1.75 m) to that side.
RelativeSector relative_sector(const KinematicState& a, double a_length, const KinematicState& b,
                               double b_length);
std::optional<RelativeSector> relative_sector_named(std::string_view word);

}  // namespace scenfuzz
