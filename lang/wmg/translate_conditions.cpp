// WHEN, WHILE and END conditions as formulas (docs/wmg-semantics.md, "Conditions", and "Encoding
// in the IR"): a signal is a SpecTerm of kind signal named after the contract's function
// (`speed`, `lane`, `timer`, ...) whose operands are word terms naming actors, lights or timers;
// it is compared with a number term (SI) or a word term (an enumeration value, a lane id).
#include <string>
#include <variant>

#include "lang/formula_builders.hpp"
#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {

namespace {

constexpr double kKilometresPerHour = 3.6;

SpecTerm word(const std::string& text, SourceLocation location) {
  return word_term(text, location);
}

SpecTerm signal(const std::string& name, const std::vector<std::string>& arguments,
                SourceLocation location) {
  std::vector<SpecTerm> operands;
  for (const std::string& argument : arguments) operands.push_back(word_term(argument, location));
  return signal_term(name.c_str(), location, std::move(operands));
}

SpecTerm number(Value value, SourceLocation location) {
  return value_term(std::move(value), location);
}

Formula compare(SpecTerm left, CompareOp op, SpecTerm right, SourceLocation location) {
  return comparison(op, std::move(left), std::move(right), location);
}

// The formulas joined by `&`, left to right; a single formula stands alone.
Formula all_of(std::vector<Formula> formulas, SourceLocation location) {
  Formula result = std::move(formulas.front());
  for (std::size_t i = 1; i < formulas.size(); ++i) {
    result =
        combined(FormulaKind::conjunction, std::move(result), std::move(formulas[i]), location);
  }
  return result;
}

CompareOp compare_op(Comparison comparison) {
  switch (comparison) {
    case Comparison::less: return CompareOp::less;
    case Comparison::less_equal: return CompareOp::less_equal;
    case Comparison::greater: return CompareOp::greater;
    case Comparison::greater_equal: return CompareOp::greater_equal;
    case Comparison::equal: return CompareOp::equal;
    case Comparison::not_equal: return CompareOp::not_equal;
  }
  return CompareOp::equal;
}

std::string offset_signal(PositionRelation relation) {
  return relation == PositionRelation::lateral ? "lateral_offset" : "longitudinal_offset";
}

std::string colour_word(TrafficLightColour colour) {
  switch (colour) {
    case TrafficLightColour::green: return "green";
    case TrafficLightColour::amber: return "amber";
    case TrafficLightColour::red: return "red";
  }
  return "red";
}

// "Going Ahead" -> "GoingAhead": observed manoeuvres are words without blanks.
std::string manoeuvre_word(const std::string& written) {
  std::string word;
  for (char c : written)
    if (c != ' ') word += c;
  return word;
}

// `lane(A) == id`, an empty formula list when the lane is unknown (already reported).
void add_lane_formula(const std::string& actor, const LaneName& lane, Translation& translation,
                      std::vector<Formula>& formulas) {
  if (auto id = translation.lane_id(lane))
    formulas.push_back(compare(signal("lane", {actor}, lane.location), CompareOp::equal,
                               word(*id, lane.location), lane.location));
}

// `timer(T)`, or for a local timer in a phase of `owner`'s, `timer(T, owner)`: it counts from
// the owner's first phase. Without an owner (an END condition) a local timer counts from the
// start, with a warning.
Formula timer_formula(const TimerConstraint& constraint, const std::string& prefix,
                      Translation& translation, const std::string* owner) {
  const std::string& name = constraint.timer.name;
  if (!translation.timers.contains(name))
    translation.diagnostics.error(constraint.timer.location,
                                  "timer '" + name + "' is not initialised");
  std::vector<std::string> operands = {name};
  if (translation.local_timers.contains(name)) {
    if (owner) {
      operands.push_back(*owner);
    } else {
      translation.diagnostics.warning(constraint.timer.location,
                                      "local timer '" + name +
                                          "' outside a manoeuvre phase counts from the start, as a "
                                          "global timer does");
    }
  }
  return compare(signal("timer", operands, constraint.timer.location),
                 compare_op(constraint.comparison.value),
                 number(translation.number(constraint.value, prefix + constraint.timer.name, "s"),
                        constraint.value.location),
                 constraint.location);
}

Formula offset_formula(const OffsetConstraint& constraint, const std::string& prefix,
                       Translation& translation) {
  translation.check_actor(constraint.actor);
  translation.check_actor(constraint.reference);
  const std::string name = offset_signal(constraint.relation.value);
  return compare(
      signal(name, {constraint.actor.name, constraint.reference.name}, constraint.location),
      compare_op(constraint.comparison.value),
      number(translation.number(constraint.value, prefix + name, "m"), constraint.value.location),
      constraint.location);
}

// `A in lane` and, when written, where it stands relative to another actor: at least the
// written offsets and relative heading, in the written sector.
Formula lane_formula(const LaneConstraint& constraint, const std::string& prefix,
                     Translation& translation) {
  translation.check_actor(constraint.actor);
  const std::string& actor = constraint.actor.name;
  std::vector<Formula> formulas;
  add_lane_formula(actor, constraint.lane, translation, formulas);
  if (constraint.placement) {
    const RelativePlacement& placement = *constraint.placement;
    translation.check_actor(placement.reference);
    const std::string& reference = placement.reference.name;
    for (const OffsetRelation& offset : placement.offsets) {
      const std::string name = offset_signal(offset.relation.value);
      formulas.push_back(compare(
          signal(name, {actor, reference}, offset.location), CompareOp::greater_equal,
          number(translation.number(offset.offset, prefix + name, "m"), offset.offset.location),
          offset.location));
    }
    if (placement.relative_position)
      formulas.push_back(compare(
          signal("relative_location", {actor, reference}, placement.relative_position->location),
          CompareOp::equal,
          word(sector_text(placement.relative_position->value),
               placement.relative_position->location),
          placement.relative_position->location));
    if (placement.relative_heading)
      formulas.push_back(compare(
          signal("relative_heading", {actor, reference}, placement.relative_heading->location),
          CompareOp::greater_equal,
          number(translation.number(*placement.relative_heading, prefix + "relative_heading", "deg",
                                    1.0, ParameterKind::angle),
                 placement.relative_heading->location),
          placement.relative_heading->location));
  }
  // Only after an unknown lane was reported: the written name keeps the formula well formed.
  if (formulas.empty())
    formulas.push_back(compare(
        signal("lane", {actor}, constraint.location), CompareOp::equal,
        word(constraint.lane.road.name + "." + constraint.lane.lane.name, constraint.lane.location),
        constraint.location));
  return all_of(std::move(formulas), constraint.location);
}

Formula actor_formula(const ActorCondition& condition, const std::string& prefix,
                      Translation& translation, std::map<std::string, Value>& speeds) {
  translation.check_actor(condition.actor);
  const std::string& actor = condition.actor.name;
  std::vector<Formula> formulas;
  formulas.push_back(
      compare(signal("manoeuvre", {actor}, condition.observed.location), CompareOp::equal,
              word(manoeuvre_word(condition.observed.text), condition.observed.location),
              condition.observed.location));
  if (condition.in_lane) add_lane_formula(actor, *condition.in_lane, translation, formulas);
  if (condition.in_element) {
    if (!translation.elements.contains(condition.in_element->name))
      translation.diagnostics.error(condition.in_element->location,
                                    "unknown element '" + condition.in_element->name +
                                        "': no junction or road structure has this id");
    formulas.push_back(compare(signal("element", {actor}, condition.in_element->location),
                               CompareOp::equal,
                               word(condition.in_element->name, condition.in_element->location),
                               condition.in_element->location));
  }
  if (condition.speed) {
    // One range is one parameter p, the speed the actor starts with; the band [p, p] holds when
    // the sequence is armed because the actor starts at exactly p.
    const SourceLocation where = condition.speed->location;
    Value speed =
        translation.number(*condition.speed, prefix + actor + ".speed", "km/h", kKilometresPerHour);
    speeds.emplace(actor, speed);
    formulas.push_back(compare(signal("speed", {actor}, where), CompareOp::greater_equal,
                               number(speed, where), where));
    formulas.push_back(compare(signal("speed", {actor}, where), CompareOp::less_equal,
                               number(speed, where), where));
  }
  return all_of(std::move(formulas), condition.location);
}

Formula light_formula(const TrafficLightCondition& condition, Translation& translation) {
  std::vector<Formula> formulas;
  for (const Identifier& light : condition.lights) {
    auto placed = translation.traffic_lights.find(light.name);
    if (placed == translation.traffic_lights.end()) {
      translation.diagnostics.error(light.location,
                                    "unknown traffic light '" + light.name +
                                        "': no junction places it (Traffic light [...] as [...])");
      continue;
    }
    formulas.push_back(compare(signal("light", {placed->second}, light.location), CompareOp::equal,
                               word(colour_word(condition.colour.value), condition.colour.location),
                               light.location));
  }
  // Only after errors: the written name keeps the formula well formed.
  if (formulas.empty())
    formulas.push_back(compare(
        signal("light", {condition.lights.front().name}, condition.location), CompareOp::equal,
        word(colour_word(condition.colour.value), condition.location), condition.location));
  return all_of(std::move(formulas), condition.location);
}

}  // namespace

Formula when_formula(const std::vector<WhenCondition>& conditions, const std::string& prefix,
                     Translation& translation, std::map<std::string, Value>& speeds) {
  std::vector<Formula> formulas;
  for (const WhenCondition& condition : conditions) {
    if (const auto* actor = std::get_if<ActorCondition>(&condition)) {
      formulas.push_back(actor_formula(*actor, prefix, translation, speeds));
    } else {
      formulas.push_back(light_formula(std::get<TrafficLightCondition>(condition), translation));
    }
  }
  return all_of(std::move(formulas),
                conditions.front().index() == 0
                    ? std::get<ActorCondition>(conditions.front()).location
                    : std::get<TrafficLightCondition>(conditions.front()).location);
}

Formula while_formula(const WhileConstraint& constraint, const std::string& prefix,
                      Translation& translation, const std::string& actor) {
  if (const auto* timer = std::get_if<TimerConstraint>(&constraint))
    return timer_formula(*timer, prefix, translation, &actor);
  if (const auto* offset = std::get_if<OffsetConstraint>(&constraint))
    return offset_formula(*offset, prefix, translation);
  return lane_formula(std::get<LaneConstraint>(constraint), prefix, translation);
}

Formula end_formula(const EndCondition& condition, const std::string& prefix,
                    Translation& translation) {
  if (const auto* timer = std::get_if<TimerConstraint>(&condition))
    return timer_formula(*timer, prefix, translation, nullptr);
  if (const auto* offset = std::get_if<OffsetConstraint>(&condition))
    return offset_formula(*offset, prefix, translation);
  if (const auto* lane = std::get_if<LaneConstraint>(&condition))
    return lane_formula(*lane, prefix, translation);
  const auto& collision = std::get<CollisionCondition>(condition);
  Formula formula;
  formula.kind = FormulaKind::predicate;
  formula.terms = {signal("collision", {}, collision.location)};
  formula.location = collision.location;
  return formula;
}

}  // namespace scenfuzz::wmg
