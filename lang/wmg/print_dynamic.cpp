// Prints DYNAMIC_ELEMENTS: the initialisation, the manoeuvre sequences, the end conditions.
#include <string>
#include <variant>

#include "lang/wmg/printer_parts.hpp"
#include "lang/wmg/syntax_printer.hpp"

namespace scenfuzz::wmg::detail {

namespace {

std::string comparison_text(Comparison comparison) {
  switch (comparison) {
    case Comparison::less: return "<";
    case Comparison::less_equal: return "<=";
    case Comparison::greater: return ">";
    case Comparison::greater_equal: return ">=";
    case Comparison::equal: return "==";
    case Comparison::not_equal: return "!=";
  }
  return "==";
}

std::string relative_location_text(RelativeLocation location) {
  return phrase_of(vocabulary::relative_location(), location);
}

std::string offsets_text(const std::vector<OffsetRelation>& offsets) {
  std::vector<std::string> texts;
  for (const OffsetRelation& offset : offsets)
    texts.push_back("with a " +
                    bracketed(phrase_of(vocabulary::position_relation(), offset.relation.value)) +
                    " offset of " + bracketed(range_text(offset.offset)));
  return joined(texts, " AND ");
}

std::string actor_start_text(const Located<ActorType>& type, const Identifier& actor,
                             const LaneName& lane) {
  return phrase_of(vocabulary::actor_type(), type.value) + " " + bracketed(actor.name) + " in " +
         bracketed(lane_text(lane));
}

std::string initialisation_text(const Initialisation& initialisation) {
  const AbsoluteActorInit& first = initialisation.first;
  std::string out = "INITIAL:\n  " + actor_start_text(first.type, first.actor, first.lane);
  if (first.position)
    out += " at " + bracketed(range_text(first.position->x) + ", " + range_text(first.position->y));
  if (first.heading) out += " at heading angle " + bracketed(range_text(*first.heading));
  out += "\n";
  for (const RelativeActorInit& init : initialisation.relative) {
    out += "  AND " + actor_start_text(init.type, init.actor, init.lane) + "\n";
    if (!init.offsets.empty()) out += "      " + offsets_text(init.offsets) + "\n";
    out += "      AND at relative position " +
           bracketed(relative_location_text(init.relative_position.value)) + "\n";
    out += "      with relative heading angle " + bracketed(range_text(init.relative_heading)) +
           " to " + bracketed(init.reference.name) + "\n";
  }
  for (const TimerInit& timer : initialisation.timers)
    out += "  AND " + phrase_of(vocabulary::timer_scope(), timer.scope.value) + " " +
           bracketed(timer.timer.name) + " = " + bracketed(range_text(timer.value)) + "\n";
  return out;
}

std::string when_condition_text(const WhenCondition& condition) {
  if (const auto* light = std::get_if<TrafficLightCondition>(&condition)) {
    std::vector<std::string> names;
    for (const Identifier& id : light->lights) names.push_back(id.name);
    return bracketed(joined(names)) + (names.size() > 1 ? " are " : " is ") +
           bracketed(phrase_of(vocabulary::traffic_light_colour(), light->colour.value));
  }
  const auto& actor = std::get<ActorCondition>(condition);
  std::string out = bracketed(actor.actor.name) + " is " + bracketed(label_text(actor.observed));
  if (actor.in_lane) out += " in " + bracketed(lane_text(*actor.in_lane));
  if (actor.in_element) out += " in " + bracketed(actor.in_element->name);
  if (actor.speed) out += " at a speed of " + bracketed(range_text(*actor.speed));
  return out;
}

std::string placement_text(const RelativePlacement& placement) {
  std::vector<std::string> parts;
  if (!placement.offsets.empty()) parts.push_back(offsets_text(placement.offsets));
  if (placement.relative_position)
    parts.push_back("AND at relative position " +
                    bracketed(relative_location_text(placement.relative_position->value)));
  if (placement.relative_heading)
    parts.push_back("with relative heading angle " +
                    bracketed(range_text(*placement.relative_heading)));
  parts.push_back("to " + bracketed(placement.reference.name));
  return joined(parts, " ");
}

struct ConstraintText {
  std::string operator()(const TimerConstraint& c) const {
    return bracketed(c.timer.name) + " " + comparison_text(c.comparison.value) + " " +
           bracketed(range_text(c.value));
  }
  std::string operator()(const OffsetConstraint& c) const {
    return bracketed(c.actor.name) + " " +
           bracketed(phrase_of(vocabulary::position_relation(), c.relation.value)) + " offset to " +
           bracketed(c.reference.name) + " " + comparison_text(c.comparison.value) + " " +
           bracketed(range_text(c.value));
  }
  std::string operator()(const LaneConstraint& c) const {
    std::string out = bracketed(c.actor.name) + " in " + bracketed(lane_text(c.lane));
    if (c.placement) out += " " + placement_text(*c.placement);
    return out;
  }
  std::string operator()(const CollisionCondition&) const { return "Collision"; }
};

std::string phase_text(const ManoeuvrePhase& phase) {
  const AgentParameters& agent = phase.agent;
  std::string out =
      "  PHASE " + std::to_string(phase.number.value) + ": " + bracketed(label_text(phase.type)) +
      " " +
      bracketed((agent.agent ? agent.agent->name : "-") + ", " + range_text(agent.first) + ", " +
                range_text(agent.second)) +
      " " +
      bracketed(phase.relative.reference.name + ": " + range_text(phase.relative.distance) + ", " +
                relative_location_text(phase.relative.relative_location.value)) +
      "\n";
  if (phase.while_constraint)
    out += "    WHILE: " + std::visit(ConstraintText{}, *phase.while_constraint) + "\n";
  return out;
}

std::string ssms_text(const Ssms& ssms) {
  std::vector<std::string> conditions;
  for (const WhenCondition& condition : ssms.conditions)
    conditions.push_back(when_condition_text(condition));
  std::string out = "WHEN: " + joined(conditions, " AND ") + "\nDO:";
  if (ssms.autonomous) return out + " AUTO\n";
  for (std::size_t i = 0; i < ssms.sequences.size(); ++i) {
    const ManoeuvreSequence& sequence = ssms.sequences[i];
    out += std::string(i == 0 ? " " : "  AND: ") + bracketed(sequence.actor.name) + "\n";
    for (const ManoeuvrePhase& phase : sequence.phases) out += phase_text(phase);
  }
  return out;
}

}  // namespace

std::string print_dynamics(const Dynamics& dynamics) {
  std::string out = "DYNAMIC ELEMENTS:\n" + initialisation_text(dynamics.initialisation);
  for (const Ssms& ssms : dynamics.sequences) out += "\n" + ssms_text(ssms);
  out += "\nEND";
  std::vector<std::string> conditions;
  for (const EndCondition& condition : dynamics.end_conditions)
    conditions.push_back(std::visit(ConstraintText{}, condition));
  if (!conditions.empty()) out += ": " + joined(conditions, " OR ");
  return out + "\n";
}

}  // namespace scenfuzz::wmg::detail
