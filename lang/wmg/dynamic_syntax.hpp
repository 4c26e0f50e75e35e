// The dynamic part of a level-2 file (DYNAMIC_ELEMENTS): where the actors start, the
// synchronised serial manoeuvre sequences (WHEN ... DO ...) and how the scenario ends.
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "lang/wmg/syntax_values.hpp"

namespace scenfuzz::wmg {

enum class ActorType { vehicle, pedestrian, cyclist };

// RELATIVE_LOCATION, written F FSR SR RSR R RSL SL FSL.
enum class RelativeLocation {
  front,             // F
  front_side_right,  // FSR
  side_right,        // SR
  rear_side_right,   // RSR
  rear,              // R
  rear_side_left,    // RSL
  side_left,         // SL
  front_side_left,   // FSL
};

enum class PositionRelation { lateral, longitudinal };

enum class Comparison { less, less_equal, greater, greater_equal, equal, not_equal };

enum class TrafficLightColour { green, amber, red };

enum class TimerScope { global, local };

// "with a [Lateral] offset of [0.5 to 1.0]".
struct OffsetRelation {
  Located<PositionRelation> relation;
  NumberRange offset;
  SourceLocation location;
  bool operator==(const OffsetRelation&) const = default;
};

// ABS_LOCATION: "at [x, y]".
struct AbsolutePosition {
  NumberRange x;
  NumberRange y;
  SourceLocation location;
  bool operator==(const AbsolutePosition&) const = default;
};

// ABS_VEHICLE_INIT: "Vehicle [Ego] in [R1.L1] at [10, 0] at heading angle [0 to 5]".
struct AbsoluteActorInit {
  Located<ActorType> type;
  Identifier actor;
  LaneName lane;
  std::optional<AbsolutePosition> position;
  std::optional<NumberRange> heading;
  SourceLocation location;
  bool operator==(const AbsoluteActorInit&) const = default;
};

// REL_VEHICLE_INIT: "Vehicle [Cutter] in [R1.L2] with a [Longitudinal] offset of [10 to 30]
// AND at relative position [FSL] with relative heading angle [0] to [Ego]".
struct RelativeActorInit {
  Located<ActorType> type;
  Identifier actor;
  LaneName lane;
  std::vector<OffsetRelation> offsets;  // none, one or two
  Located<RelativeLocation> relative_position;
  NumberRange relative_heading;
  Identifier reference;
  SourceLocation location;
  bool operator==(const RelativeActorInit&) const = default;
};

// "Global timer [T1] = [0]" or "Local timer [T2] = [0]".
struct TimerInit {
  Located<TimerScope> scope;
  Identifier timer;
  NumberRange value;
  SourceLocation location;
  bool operator==(const TimerInit&) const = default;
};

// INITIALISATION: one actor placed absolutely, the others relative to actors before them.
struct Initialisation {
  AbsoluteActorInit first;
  std::vector<RelativeActorInit> relative;
  std::vector<TimerInit> timers;
  SourceLocation location;
  bool operator==(const Initialisation&) const = default;
};

// EGO_POSITION_CONDITION: "[Ego] is [Going Ahead] in [R1.L1] at a speed of [60 to 80]"; the
// place is a lane or another element's ID (at most one of the two).
struct ActorCondition {
  Identifier actor;
  Label observed;
  std::optional<LaneName> in_lane;
  std::optional<Identifier> in_element;
  std::optional<NumberRange> speed;
  SourceLocation location;
  bool operator==(const ActorCondition&) const = default;
};

// TRAFFIC_LIGHT_CONDITION: "[TL1, TL2] are [Green]".
struct TrafficLightCondition {
  std::vector<Identifier> lights;
  Located<TrafficLightColour> colour;
  SourceLocation location;
  bool operator==(const TrafficLightCondition&) const = default;
};

using WhenCondition = std::variant<ActorCondition, TrafficLightCondition>;

// TIMER_CONSTRAINT: "[T1] >= [5]".
struct TimerConstraint {
  Identifier timer;
  Located<Comparison> comparison;
  NumberRange value;
  SourceLocation location;
  bool operator==(const TimerConstraint&) const = default;
};

// The first form of POSITION_CONSTRAINT: "[Cutter] [Longitudinal] offset to [Ego] < [10]".
struct OffsetConstraint {
  Identifier actor;
  Located<PositionRelation> relation;
  Identifier reference;
  Located<Comparison> comparison;
  NumberRange value;
  SourceLocation location;
  bool operator==(const OffsetConstraint&) const = default;
};

// The optional tail of a lane constraint: offsets, relative position and heading, "to [ID]".
struct RelativePlacement {
  std::vector<OffsetRelation> offsets;  // none, one or two
  std::optional<Located<RelativeLocation>> relative_position;
  std::optional<NumberRange> relative_heading;
  Identifier reference;
  SourceLocation location;
  bool operator==(const RelativePlacement&) const = default;
};

// The second form of POSITION_CONSTRAINT: "[Cutter] in [R1.L1] AND at relative position [F]
// to [Ego]".
struct LaneConstraint {
  Identifier actor;
  LaneName lane;
  std::optional<RelativePlacement> placement;
  SourceLocation location;
  bool operator==(const LaneConstraint&) const = default;
};

// "Collision" as an end condition.
struct CollisionCondition {
  SourceLocation location;
  bool operator==(const CollisionCondition&) const = default;
};

using WhileConstraint = std::variant<TimerConstraint, OffsetConstraint, LaneConstraint>;
using EndCondition =
    std::variant<TimerConstraint, OffsetConstraint, LaneConstraint, CollisionCondition>;

// MP_AGENT_PARAMS: "[-, 60 to 80, 1 to 3]" or "[Ego, 60 to 80, 1 to 3]". The grammar names
// neither range; the translation gives them their meaning.
struct AgentParameters {
  std::optional<Identifier> agent;  // empty for '-'
  NumberRange first;
  NumberRange second;
  SourceLocation location;
  bool operator==(const AgentParameters&) const = default;
};

// MP_RELATIVE_AGENT_PARAMS: "[Ego: 10 to 30, FSL]".
struct RelativeAgentParameters {
  Identifier reference;
  NumberRange distance;
  Located<RelativeLocation> relative_location;
  SourceLocation location;
  bool operator==(const RelativeAgentParameters&) const = default;
};

// MANOEUVRE_PHASE: "PHASE 1: [Drive_CutIn] [...] [...] WHILE: ...".
struct ManoeuvrePhase {
  WholeNumber number;
  Label type;  // one of the grammar's MP_TYPE words, canonical spelling
  AgentParameters agent;
  RelativeAgentParameters relative;
  std::optional<WhileConstraint> while_constraint;
  SourceLocation location;
  bool operator==(const ManoeuvrePhase&) const = default;
};

// SERIAL_MANOEUVRE_SEQ: "[Cutter] PHASE 1: ... PHASE 2: ...".
struct ManoeuvreSequence {
  Identifier actor;
  std::vector<ManoeuvrePhase> phases;
  SourceLocation location;
  bool operator==(const ManoeuvreSequence&) const = default;
};

// SSMS: "WHEN: conditions DO: sequences" or "DO: AUTO" (autonomous: no sequences).
struct Ssms {
  std::vector<WhenCondition> conditions;
  bool autonomous = false;
  std::vector<ManoeuvreSequence> sequences;
  SourceLocation location;
  bool operator==(const Ssms&) const = default;
};

// DYNAMIC_ELEMENTS. end_conditions is empty for a bare "END".
struct Dynamics {
  Initialisation initialisation;
  std::vector<Ssms> sequences;
  std::vector<EndCondition> end_conditions;  // joined by OR
  SourceLocation location;
  bool operator==(const Dynamics&) const = default;
};

}  // namespace scenfuzz::wmg
