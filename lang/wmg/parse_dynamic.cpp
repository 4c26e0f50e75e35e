// DYNAMIC_ELEMENTS: the actors' initialisation, the synchronised serial manoeuvre sequences and
// the end conditions. A manoeuvre phase with an error is reported and the parser resumes at the
// next phase, sequence, WHEN or END.
#include <string>

#include "lang/wmg/parse_sections.hpp"

namespace scenfuzz::wmg::detail {

namespace {

constexpr TokenKind kComma = TokenKind::comma;
constexpr TokenKind kOpen = TokenKind::left_bracket;
constexpr TokenKind kClose = TokenKind::right_bracket;

bool at_sequence_separator(const Cursor& cursor) {
  return cursor.at_word("AND") && cursor.at(TokenKind::colon, 1);
}

bool at_comparison(const Cursor& cursor) {
  switch (cursor.peek().kind) {
    case TokenKind::less:
    case TokenKind::less_equal:
    case TokenKind::greater:
    case TokenKind::greater_equal:
    case TokenKind::equal:
    case TokenKind::not_equal: return true;
    default: return false;
  }
}

Located<Comparison> parse_comparison(Cursor& cursor, const std::string& context) {
  if (!at_comparison(cursor))
    cursor.fail(cursor.peek().location, "expected a comparison (<, <=, >, >=, == or !=) " +
                                            context + ", found " + describe(cursor.peek()));
  Located<Comparison> result;
  result.location = cursor.peek().location;
  switch (cursor.take().kind) {
    case TokenKind::less: result.value = Comparison::less; break;
    case TokenKind::less_equal: result.value = Comparison::less_equal; break;
    case TokenKind::greater: result.value = Comparison::greater; break;
    case TokenKind::greater_equal: result.value = Comparison::greater_equal; break;
    case TokenKind::equal: result.value = Comparison::equal; break;
    default: result.value = Comparison::not_equal; break;
  }
  return result;
}

OffsetRelation parse_offset_relation(Cursor& cursor) {
  OffsetRelation offset;
  SourceLocation first = cursor.expect_phrase("with a", "");
  offset.relation = cursor.bracketed_enumerated<PositionRelation>(vocabulary::position_relation());
  cursor.expect_phrase("offset of", "after the position relation");
  offset.offset = cursor.bracketed_range("the offset");
  offset.location = cursor.span_from(first);
  return offset;
}

// [OFFSET_RELATION [AND OFFSET_RELATION]]
std::vector<OffsetRelation> parse_offsets(Cursor& cursor) {
  std::vector<OffsetRelation> offsets;
  if (!cursor.at_phrase("with a")) return offsets;
  offsets.push_back(parse_offset_relation(cursor));
  if (cursor.at_phrase("AND with a")) {
    cursor.take();
    offsets.push_back(parse_offset_relation(cursor));
  }
  return offsets;
}

TimerInit parse_timer_init(Cursor& cursor) {
  TimerInit timer;
  timer.scope = cursor.enumerated<TimerScope>(vocabulary::timer_scope());
  timer.timer = cursor.bracketed_id("the timer");
  cursor.expect(TokenKind::assign, "after the timer's ID");
  timer.value = cursor.bracketed_number("the timer's initial value");
  timer.location = cursor.span_from(timer.scope.location);
  return timer;
}

struct ActorStart {
  Located<ActorType> type;
  Identifier actor;
  LaneName lane;
};

// ACTOR_TYPE '[' ID ']' in '[' ROAD_LANE_QNAME ']': how both kinds of actor init begin.
ActorStart parse_actor_start(Cursor& cursor) {
  ActorStart start;
  start.type = cursor.enumerated<ActorType>(vocabulary::actor_type());
  start.actor = cursor.bracketed_id("the actor");
  cursor.expect_phrase("in", "after the actor '" + start.actor.name + "'");
  start.lane = cursor.bracketed_lane_name("the actor's lane");
  return start;
}

bool at_relative_placement(const Cursor& cursor) {
  return cursor.at_phrase("with a") || cursor.at_phrase("AND at relative position");
}

AbsoluteActorInit parse_absolute_init(Cursor& cursor, ActorStart start) {
  AbsoluteActorInit init{start.type, start.actor, start.lane, {}, {}, {}};
  if (cursor.at_word("at") && cursor.at(kOpen, 1)) {
    cursor.take();
    AbsolutePosition position;
    position.location = cursor.expect(kOpen, "before the position").location;
    position.x = cursor.number("the x coordinate");
    cursor.expect(kComma, "between the x and y coordinates");
    position.y = cursor.number("the y coordinate");
    cursor.close(kClose, "after the position");
    position.location = cursor.span_from(position.location);
    init.position = position;
  }
  if (cursor.at_phrase("at heading angle")) {
    cursor.expect_phrase("at heading angle", "");
    init.heading = cursor.bracketed_range("the heading angle");
  }
  init.location = cursor.span_from(start.type.location);
  return init;
}

RelativeActorInit parse_relative_init(Cursor& cursor, ActorStart start) {
  RelativeActorInit init;
  init.type = start.type;
  init.actor = start.actor;
  init.lane = start.lane;
  init.offsets = parse_offsets(cursor);
  cursor.expect_phrase("AND at relative position",
                       "after the lane of '" + init.actor.name +
                           "': only the first actor is placed absolutely, the others relative "
                           "to an actor before them");
  init.relative_position =
      cursor.bracketed_enumerated<RelativeLocation>(vocabulary::relative_location());
  cursor.expect_phrase("with relative heading angle", "after the relative position");
  init.relative_heading = cursor.bracketed_range("the relative heading angle");
  cursor.expect_phrase("to", "after the relative heading angle");
  init.reference = cursor.bracketed_id("the actor it is placed relative to");
  init.location = cursor.span_from(start.type.location);
  return init;
}

Initialisation parse_initialisation(Cursor& cursor) {
  Initialisation initialisation;
  SourceLocation first = cursor.expect_phrase("INITIAL", "after 'DYNAMIC ELEMENTS:'");
  cursor.expect(TokenKind::colon, "after 'INITIAL'");
  ActorStart start = parse_actor_start(cursor);
  if (at_relative_placement(cursor))
    cursor.fail(cursor.peek().location,
                "the first actor is placed absolutely (in a lane, optionally 'at [x, y]' and 'at "
                "heading angle [...]'); relative placements are for the actors after it");
  initialisation.first = parse_absolute_init(cursor, start);
  // Relative actors and timers follow, each after AND; the grammar puts the timers last, but
  // their order carries no meaning, so either order is read.
  while (cursor.at_word("AND")) {
    cursor.take();
    if (cursor.at_phrase("Global timer") || cursor.at_phrase("Local timer")) {
      initialisation.timers.push_back(parse_timer_init(cursor));
    } else {
      initialisation.relative.push_back(parse_relative_init(cursor, parse_actor_start(cursor)));
    }
  }
  initialisation.location = cursor.span_from(first);
  return initialisation;
}

bool at_traffic_light_colour(const Cursor& cursor) {
  return cursor.at_phrase("Green") || cursor.at_phrase("Amber") || cursor.at_phrase("Red");
}

WhenCondition parse_when_condition(Cursor& cursor) {
  SourceLocation first =
      cursor.expect(kOpen, "before the actor or traffic lights of a condition").location;
  std::vector<Identifier> ids{cursor.id("the actor or traffic light")};
  while (cursor.at(kComma)) {
    cursor.take();
    ids.push_back(cursor.id("a traffic light"));
  }
  cursor.close(kClose, "after the actor or traffic lights");
  bool plural = cursor.at_word("are");
  if (!plural)
    cursor.expect_phrase("is", "after '[" + ids.front().name + "]'");
  else
    cursor.take();
  cursor.expect(kOpen, plural ? "after 'are'" : "after 'is'");
  if (plural || ids.size() > 1 || at_traffic_light_colour(cursor)) {
    TrafficLightCondition condition;
    condition.lights = ids;
    condition.colour = cursor.enumerated<TrafficLightColour>(vocabulary::traffic_light_colour());
    cursor.close(kClose, "after the traffic light colour");
    condition.location = cursor.span_from(first);
    return condition;
  }
  ActorCondition condition;
  condition.actor = ids.front();
  condition.observed = cursor.label(vocabulary::observed_manoeuvre());
  cursor.close(kClose, "after the observed manoeuvre");
  if (cursor.at_word("in")) {
    cursor.take();
    cursor.expect(kOpen, "after 'in'");
    if (cursor.at_road_id())
      condition.in_lane = cursor.lane_name("the actor's lane");
    else
      condition.in_element = cursor.id("the place the actor is in");
    cursor.close(kClose, "after the place the actor is in");
  }
  if (cursor.at_phrase("at a speed of")) {
    cursor.expect_phrase("at a speed of", "");
    condition.speed = cursor.bracketed_range("the actor's speed");
  }
  condition.location = cursor.span_from(first);
  return condition;
}

bool at_placement(const Cursor& cursor) {
  return cursor.at_phrase("with a") || cursor.at_phrase("AND at relative position") ||
         cursor.at_phrase("with relative heading angle");
}

RelativePlacement parse_placement(Cursor& cursor) {
  RelativePlacement placement;
  SourceLocation first = cursor.peek().location;
  placement.offsets = parse_offsets(cursor);
  if (cursor.at_phrase("AND at relative position")) {
    cursor.expect_phrase("AND at relative position", "");
    placement.relative_position =
        cursor.bracketed_enumerated<RelativeLocation>(vocabulary::relative_location());
  }
  if (cursor.at_phrase("with relative heading angle")) {
    cursor.expect_phrase("with relative heading angle", "");
    placement.relative_heading = cursor.bracketed_range("the relative heading angle");
  }
  cursor.expect_phrase("to", "after the relative placement");
  placement.reference = cursor.bracketed_id("the actor it is placed relative to");
  placement.location = cursor.span_from(first);
  return placement;
}

// TIMER_CONSTRAINT or either form of POSITION_CONSTRAINT (or, ending the scenario, Collision).
EndCondition parse_constraint(Cursor& cursor, bool allow_collision) {
  if (allow_collision && cursor.at_phrase("Collision"))
    return CollisionCondition{cursor.expect_phrase("Collision", "")};
  SourceLocation first = cursor.peek().location;
  Identifier subject = cursor.bracketed_id("the timer or actor of a constraint");
  if (at_comparison(cursor)) {
    TimerConstraint constraint;
    constraint.timer = subject;
    constraint.comparison = parse_comparison(cursor, "after the timer");
    constraint.value = cursor.bracketed_number("the timer's value");
    constraint.location = cursor.span_from(first);
    return constraint;
  }
  if (cursor.at(kOpen)) {
    OffsetConstraint constraint;
    constraint.actor = subject;
    constraint.relation =
        cursor.bracketed_enumerated<PositionRelation>(vocabulary::position_relation());
    cursor.expect_phrase("offset to", "after the position relation");
    constraint.reference = cursor.bracketed_id("the reference actor");
    constraint.comparison = parse_comparison(cursor, "after the reference actor");
    constraint.value = cursor.bracketed_number("the offset's bound");
    constraint.location = cursor.span_from(first);
    return constraint;
  }
  if (cursor.at_word("in")) {
    cursor.take();
    LaneConstraint constraint;
    constraint.actor = subject;
    constraint.lane = cursor.bracketed_lane_name("the actor's lane");
    if (at_placement(cursor)) constraint.placement = parse_placement(cursor);
    constraint.location = cursor.span_from(first);
    return constraint;
  }
  cursor.fail(cursor.peek().location,
              "expected a comparison (timer), '[Lateral]' or '[Longitudinal]' (offset) or "
              "'in [R1.L1]' (lane) after '[" +
                  subject.name + "]', found " + describe(cursor.peek()));
}

WhileConstraint while_constraint(EndCondition condition) {
  if (auto* timer = std::get_if<TimerConstraint>(&condition)) return *timer;
  if (auto* offset = std::get_if<OffsetConstraint>(&condition)) return *offset;
  return std::get<LaneConstraint>(condition);
}

AgentParameters parse_agent_parameters(Cursor& cursor) {
  AgentParameters parameters;
  SourceLocation first = cursor.expect(kOpen, "before the agent parameters").location;
  if (cursor.at(TokenKind::minus)) {
    cursor.take();
  } else if (cursor.at_road_id()) {
    // A road: the one a crossing crosses (docs/wmg-semantics.md, "Manoeuvre phases").
    parameters.agent = cursor.road_id("the agent");
  } else {
    parameters.agent = cursor.id("the agent (or '-' for none)");
  }
  cursor.expect(kComma, "after the agent");
  parameters.first = cursor.range(kComma, "the agent's first parameter");
  cursor.expect(kComma, "after the agent's first parameter");
  parameters.second = cursor.range(kClose, "the agent's second parameter");
  cursor.close(kClose, "after the agent parameters");
  parameters.location = cursor.span_from(first);
  return parameters;
}

RelativeAgentParameters parse_relative_agent_parameters(Cursor& cursor) {
  RelativeAgentParameters parameters;
  SourceLocation first = cursor.expect(kOpen, "before the relative agent parameters").location;
  parameters.reference = cursor.id("the reference agent");
  cursor.expect(TokenKind::colon, "after the reference agent");
  parameters.distance = cursor.range(kComma, "the distance to the reference agent");
  cursor.expect(kComma, "after the distance to the reference agent");
  parameters.relative_location =
      cursor.enumerated<RelativeLocation>(vocabulary::relative_location());
  cursor.close(kClose, "after the relative location");
  parameters.location = cursor.span_from(first);
  return parameters;
}

ManoeuvrePhase parse_phase(Cursor& cursor, std::int64_t expected_number) {
  ManoeuvrePhase phase;
  SourceLocation first = cursor.expect_phrase("PHASE", "");
  phase.number = cursor.whole_number("the phase number");
  if (phase.number.value != expected_number)
    cursor.error(phase.number.location,
                 "expected PHASE " + std::to_string(expected_number) +
                     ": the phases of a sequence are numbered 1, 2, 3, ... in order");
  cursor.expect(TokenKind::colon, "after 'PHASE " + std::to_string(phase.number.value) + "'");
  phase.type = cursor.bracketed_label(vocabulary::manoeuvre_type());
  phase.agent = parse_agent_parameters(cursor);
  phase.relative = parse_relative_agent_parameters(cursor);
  if (cursor.at_word("WHILE")) {
    cursor.take();
    cursor.expect(TokenKind::colon, "after 'WHILE'");
    phase.while_constraint = while_constraint(parse_constraint(cursor, false));
  }
  phase.location = cursor.span_from(first);
  return phase;
}

bool at_dynamic_end(const Cursor& cursor) { return cursor.at_word("END"); }

ManoeuvreSequence parse_sequence(Cursor& cursor) {
  ManoeuvreSequence sequence;
  SourceLocation first = cursor.peek().location;
  sequence.actor = cursor.bracketed_id("the actor of the manoeuvre sequence");
  if (!cursor.at_phrase("PHASE"))
    cursor.fail(cursor.peek().location, "expected 'PHASE 1:' after the actor '[" +
                                            sequence.actor.name + "]', found " +
                                            describe(cursor.peek()));
  std::int64_t expected_number = 1;
  do {
    std::size_t start = cursor.position();
    try {
      sequence.phases.push_back(parse_phase(cursor, expected_number));
    } catch (const SyntaxError&) {
      cursor.resync(start, [&] {
        return cursor.at_phrase("PHASE") || at_sequence_separator(cursor) ||
               cursor.at_word("WHEN") || at_dynamic_end(cursor);
      });
    }
    ++expected_number;
  } while (cursor.at_phrase("PHASE"));
  sequence.location = cursor.span_from(first);
  return sequence;
}

Ssms parse_ssms(Cursor& cursor) {
  Ssms ssms;
  SourceLocation first = cursor.expect_phrase("WHEN", "");
  cursor.expect(TokenKind::colon, "after 'WHEN'");
  ssms.conditions.push_back(parse_when_condition(cursor));
  while (cursor.at_word("AND")) {
    cursor.take();
    ssms.conditions.push_back(parse_when_condition(cursor));
  }
  cursor.expect_phrase("DO", "after the WHEN conditions");
  cursor.expect(TokenKind::colon, "after 'DO'");
  if (cursor.at_word("AUTO")) {
    cursor.take();
    ssms.autonomous = true;
  } else {
    ssms.sequences.push_back(parse_sequence(cursor));
    while (at_sequence_separator(cursor)) {
      cursor.take();
      cursor.take();
      ssms.sequences.push_back(parse_sequence(cursor));
    }
  }
  ssms.location = cursor.span_from(first);
  return ssms;
}

}  // namespace

Dynamics parse_dynamics(Cursor& cursor) {
  Dynamics dynamics;
  SourceLocation first = cursor.expect_phrase("DYNAMIC ELEMENTS", "after the scenery");
  cursor.expect(TokenKind::colon, "after 'DYNAMIC ELEMENTS'");
  std::size_t start = cursor.position();
  try {
    dynamics.initialisation = parse_initialisation(cursor);
  } catch (const SyntaxError&) {
    cursor.resync(start, [&] { return cursor.at_word("WHEN") || at_dynamic_end(cursor); });
  }
  if (!cursor.at_word("WHEN"))
    cursor.fail(cursor.peek().location,
                "expected 'WHEN:' and the first manoeuvre sequence after the initialisation, "
                "found " +
                    describe(cursor.peek()));
  while (cursor.at_word("WHEN")) {
    start = cursor.position();
    try {
      dynamics.sequences.push_back(parse_ssms(cursor));
    } catch (const SyntaxError&) {
      cursor.resync(start, [&] { return cursor.at_word("WHEN") || at_dynamic_end(cursor); });
    }
  }
  cursor.expect_phrase("END", "after the manoeuvre sequences");
  if (cursor.at(TokenKind::colon)) {
    cursor.take();
    dynamics.end_conditions.push_back(parse_constraint(cursor, true));
    while (cursor.at_word("OR")) {
      cursor.take();
      dynamics.end_conditions.push_back(parse_constraint(cursor, true));
    }
  }
  dynamics.location = cursor.span_from(first);
  return dynamics;
}

}  // namespace scenfuzz::wmg::detail
