#include "physics/simulation/manoeuvre_trigger.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>

namespace scenfuzz {
namespace {

// What a word on the other side of a comparison means.
enum class Domain { number, lane, manoeuvre, colour, junction, sector };

// Half a lane: an actor further than this to one side of another is beside it, not in line.
constexpr double kInLineLateral = 1.75;  // m

constexpr std::array<std::string_view, 8> kSectorNames{"F", "FSR", "SR", "RSR",
                                                       "R", "RSL", "SL", "FSL"};

std::string lowercase(std::string_view text) {
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

std::optional<SignalColour> colour_word(std::string_view word) {
  std::string lower = lowercase(word);
  if (lower == "red") return SignalColour::red;
  if (lower == "yellow" || lower == "amber") return SignalColour::yellow;
  if (lower == "green") return SignalColour::green;
  return std::nullopt;
}

Domain domain_of(const SpecTerm& term) {
  if (term.kind != TermKind::signal) return Domain::number;
  std::string name = lowercase(term.name);
  if (name == "lane") return Domain::lane;
  if (name == "manoeuvre" || name == "maneuver") return Domain::manoeuvre;
  if (name == "light") return Domain::colour;
  if (name == "element") return Domain::junction;
  if (name == "relative_location") return Domain::sector;
  return Domain::number;
}

class Compiler {
 public:
  Compiler(const TriggerNames& names, Diagnostics& diagnostics)
      : names_(names), diagnostics_(diagnostics) {}

  std::optional<TriggerCondition> formula(const Formula& formula) {
    TriggerCondition condition;
    switch (formula.kind) {
      case FormulaKind::comparison: return comparison(formula);
      case FormulaKind::predicate: {
        if (formula.terms.size() != 1) return fail(formula.location, "a condition needs one term");
        auto quantity = term(formula.terms[0], Domain::number);
        if (!quantity) return std::nullopt;
        condition.kind = TriggerKind::truth;
        condition.sides.push_back(std::move(*quantity));
        return condition;
      }
      case FormulaKind::negation: condition.kind = TriggerKind::negation; break;
      case FormulaKind::conjunction: condition.kind = TriggerKind::conjunction; break;
      case FormulaKind::disjunction: condition.kind = TriggerKind::disjunction; break;
      case FormulaKind::implication: condition.kind = TriggerKind::implication; break;
      case FormulaKind::always:
      case FormulaKind::eventually:
      case FormulaKind::next:
      case FormulaKind::until:
        return fail(formula.location,
                    "a trigger or end condition holds at one instant; temporal operators (G, F, X, "
                    "U) cannot be evaluated while simulating");
    }
    std::size_t expected = condition.kind == TriggerKind::negation ? 1 : 2;
    if (formula.operands.size() != expected) return fail(formula.location, "malformed condition");
    for (const Formula& operand : formula.operands) {
      auto compiled = this->formula(operand);
      if (!compiled) return std::nullopt;
      condition.operands.push_back(std::move(*compiled));
    }
    return condition;
  }

 private:
  std::optional<TriggerCondition> comparison(const Formula& formula) {
    if (formula.terms.size() != 2) return fail(formula.location, "a comparison needs two sides");
    const SpecTerm& left = formula.terms[0];
    const SpecTerm& right = formula.terms[1];
    bool left_word = left.kind == TermKind::word;
    bool right_word = right.kind == TermKind::word;
    if (left_word && right_word)
      return fail(formula.location, "a comparison of two words ('" + left.name + "', '" +
                                        right.name + "') has no signal to evaluate");
    Domain domain = left_word ? domain_of(right) : domain_of(left);
    if (domain != Domain::number && formula.compare != CompareOp::equal &&
        formula.compare != CompareOp::not_equal)
      return fail(formula.location,
                  "lanes, manoeuvres, light colours, junctions and sectors can "
                  "only be compared with == or !=");
    auto a = term(left, domain);
    auto b = term(right, domain);
    if (!a || !b) return std::nullopt;
    TriggerCondition condition;
    condition.kind = TriggerKind::comparison;
    condition.compare = formula.compare;
    condition.sides.push_back(std::move(*a));
    condition.sides.push_back(std::move(*b));
    return condition;
  }

  std::optional<TriggerQuantity> term(const SpecTerm& term, Domain domain) {
    TriggerQuantity quantity;
    switch (term.kind) {
      case TermKind::number:
        quantity.number = evaluate(term.value, names_.values);
        if (!std::isfinite(quantity.number))
          return fail(term.location, "the number is not finite at this point of the search");
        return quantity;
      case TermKind::word: return word(term, domain);
      case TermKind::signal: return signal(term);
      case TermKind::add: quantity.signal = TriggerSignal::add; break;
      case TermKind::subtract: quantity.signal = TriggerSignal::subtract; break;
      case TermKind::multiply: quantity.signal = TriggerSignal::multiply; break;
      case TermKind::divide: quantity.signal = TriggerSignal::divide; break;
      case TermKind::negate: quantity.signal = TriggerSignal::negate; break;
      default:
        return fail(term.location,
                    "this term cannot be evaluated in a trigger (expected a number, a word or one "
                    "of speed, lane, manoeuvre, light, timer, lateral_offset, "
                    "longitudinal_offset, collision)");
    }
    std::size_t expected = quantity.signal == TriggerSignal::negate ? 1 : 2;
    if (term.operands.size() != expected) return fail(term.location, "malformed arithmetic");
    for (const SpecTerm& operand : term.operands) {
      auto compiled = this->term(operand, Domain::number);
      if (!compiled) return std::nullopt;
      quantity.operands.push_back(std::move(*compiled));
    }
    return quantity;
  }

  std::optional<TriggerQuantity> word(const SpecTerm& term, Domain domain) {
    TriggerQuantity quantity;
    switch (domain) {
      case Domain::lane: {
        auto lane = names_.map.find_lane(term.name);
        if (!lane)
          return fail(term.location,
                      "unknown lane '" + term.name + "' on map '" + names_.map.name() + "'");
        quantity.number = *lane;
        return quantity;
      }
      case Domain::manoeuvre: {
        auto manoeuvre = observed_manoeuvre_named(term.name);
        if (!manoeuvre)
          return fail(term.location, "unknown manoeuvre '" + term.name +
                                         "' (expected GoingAhead, Stopped, LaneChangeLeft, "
                                         "LaneChangeRight, TurnLeft, TurnRight or Reverse)");
        quantity.number = static_cast<double>(*manoeuvre);
        return quantity;
      }
      case Domain::colour: {
        auto colour = colour_word(term.name);
        if (!colour)
          return fail(term.location,
                      "unknown light colour '" + term.name + "' (expected red, yellow or green)");
        quantity.number = static_cast<double>(*colour);
        return quantity;
      }
      case Domain::junction: {
        const auto& junctions = names_.map.junctions();
        for (std::size_t i = 0; i < junctions.size(); ++i)
          if (junctions[i].id == term.name) {
            quantity.number = static_cast<double>(i);
            return quantity;
          }
        // A WMG SDL scenery has one junction, whose written id (J1) the generated map does not
        // keep: on a map with one junction, any junction id names it.
        if (junctions.size() == 1) return quantity;
        return fail(term.location,
                    "map '" + names_.map.name() + "' has no junction '" + term.name + "'");
      }
      case Domain::sector: {
        auto sector = relative_sector_named(term.name);
        if (!sector)
          return fail(term.location, "unknown sector '" + term.name +
                                         "' (expected F, FSR, SR, RSR, R, RSL, SL or FSL)");
        quantity.number = static_cast<double>(*sector);
        return quantity;
      }
      case Domain::number: break;
    }
    return fail(term.location, "the word '" + term.name + "' stands where a number is expected");
  }

  // The name an operand gives: a word, an object or a bare signal name all name something.
  static const std::string* operand_name(const SpecTerm& operand) {
    if (operand.name.empty() || !operand.operands.empty()) return nullptr;
    return &operand.name;
  }

  std::optional<std::uint32_t> actor(const SpecTerm& operand) {
    const std::string* name = operand_name(operand);
    if (!name) return fail(operand.location, "expected an actor's name");
    for (std::size_t id = 0; id < names_.actors.size(); ++id)
      if (names_.actors[id] == *name) return static_cast<std::uint32_t>(id);
    for (std::size_t id = 0; id < names_.actors.size(); ++id)
      if (lowercase(names_.actors[id]) == lowercase(*name)) return static_cast<std::uint32_t>(id);
    return fail(operand.location, "the condition names an unknown actor '" + *name + "'");
  }

  std::optional<TriggerQuantity> signal(const SpecTerm& term) {
    TriggerQuantity quantity;
    std::string name = lowercase(term.name);
    auto arity = [&](std::size_t count) -> bool {
      if (term.operands.size() == count) return true;
      diagnostics_.error(term.location, term.name + "(...) takes " + std::to_string(count) +
                                            " argument" + (count == 1 ? "" : "s"));
      return false;
    };
    if (name == "speed" || name == "lane" || name == "manoeuvre" || name == "maneuver" ||
        name == "element") {
      quantity.signal = name == "speed"     ? TriggerSignal::speed
                        : name == "lane"    ? TriggerSignal::lane
                        : name == "element" ? TriggerSignal::element
                                            : TriggerSignal::manoeuvre;
      if (!arity(1)) return std::nullopt;
      auto id = actor(term.operands[0]);
      if (!id) return std::nullopt;
      quantity.actor = *id;
      return quantity;
    }
    if (name == "lateral_offset" || name == "longitudinal_offset" || name == "relative_location" ||
        name == "relative_heading") {
      quantity.signal = name == "lateral_offset"        ? TriggerSignal::lateral_offset
                        : name == "longitudinal_offset" ? TriggerSignal::longitudinal_offset
                        : name == "relative_location"   ? TriggerSignal::relative_location
                                                        : TriggerSignal::relative_heading;
      if (!arity(2)) return std::nullopt;
      auto a = actor(term.operands[0]);
      auto b = actor(term.operands[1]);
      if (!a || !b) return std::nullopt;
      quantity.actor = *a;
      quantity.other = *b;
      return quantity;
    }
    if (name == "light") {
      quantity.signal = TriggerSignal::light;
      if (!arity(1)) return std::nullopt;
      const std::string* id = operand_name(term.operands[0]);
      const auto& lights = names_.map.traffic_lights();
      for (std::size_t i = 0; id && i < lights.size(); ++i)
        if (lights[i].id == *id) {
          quantity.actor = static_cast<std::uint32_t>(i);
          return quantity;
        }
      return fail(term.operands[0].location, "map '" + names_.map.name() +
                                                 "' has no traffic light '" +
                                                 (id ? *id : std::string()) + "'");
    }
    if (name == "timer") {
      // timer(T) counts from the start; timer(T, A), a local timer, from A's first phase.
      quantity.signal = TriggerSignal::timer;
      if (term.operands.size() == 2) {
        quantity.signal = TriggerSignal::local_timer;
        const auto owner = actor(term.operands[1]);
        if (!owner) return std::nullopt;
        quantity.actor = *owner;
      } else if (!arity(1)) {
        return std::nullopt;
      }
      const std::string* id = operand_name(term.operands[0]);
      for (std::size_t i = 0; id && i < names_.timers.size(); ++i)
        if (names_.timers[i] == *id) {
          quantity.number = names_.timer_initial_values[i];
          return quantity;
        }
      return fail(term.operands[0].location,
                  "unknown timer '" + (id ? *id : std::string()) + "' (declare it as a timer)");
    }
    if (name == "collision") {
      quantity.signal = TriggerSignal::collision;
      if (!arity(0)) return std::nullopt;
      return quantity;
    }
    return fail(term.location, "unknown signal '" + term.name +
                                   "' in a condition (expected speed, lane, manoeuvre, light, "
                                   "timer, lateral_offset, longitudinal_offset, collision, "
                                   "element, relative_location or relative_heading)");
  }

  std::nullopt_t fail(const SourceLocation& location, const std::string& message) {
    diagnostics_.error(location, message);
    return std::nullopt;
  }

  const TriggerNames& names_;
  Diagnostics& diagnostics_;
};

double value_of(const TriggerQuantity& quantity, const WorldSnapshot& world) {
  switch (quantity.signal) {
    case TriggerSignal::number: return quantity.number;
    case TriggerSignal::speed: return world.states[quantity.actor].speed;
    case TriggerSignal::lane: return world.lanes[quantity.actor].lane;
    case TriggerSignal::manoeuvre: return static_cast<double>(world.manoeuvres[quantity.actor]);
    case TriggerSignal::light:
      return quantity.actor < world.lights.size()
                 ? static_cast<double>(world.lights[quantity.actor])
                 : -1;
    case TriggerSignal::timer: return world.time + quantity.number;
    case TriggerSignal::local_timer: {
      // It stands at its initial value until its actor's first phase begins.
      const double began = quantity.actor < world.sequence_starts.size()
                               ? world.sequence_starts[quantity.actor]
                               : std::numeric_limits<double>::quiet_NaN();
      return std::isnan(began) ? quantity.number : quantity.number + (world.time - began);
    }
    case TriggerSignal::lateral_offset:
      return lateral_offset(world.states[quantity.actor], world.states[quantity.other]);
    case TriggerSignal::longitudinal_offset:
      return longitudinal_offset(world.states[quantity.actor], world.states[quantity.other]);
    case TriggerSignal::collision: return world.collided ? 1 : 0;
    case TriggerSignal::element: {
      std::int32_t lane = world.lanes[quantity.actor].lane;
      if (lane < 0) return -1;
      const auto& junction = world.map->lane(static_cast<LaneIndex>(lane)).junction;
      return junction ? static_cast<double>(*junction) : -1;
    }
    case TriggerSignal::relative_location:
      return static_cast<double>(
          relative_sector(world.states[quantity.actor], world.lengths[quantity.actor],
                          world.states[quantity.other], world.lengths[quantity.other]));
    case TriggerSignal::relative_heading:
      return angle_difference(world.states[quantity.actor].heading,
                              world.states[quantity.other].heading) *
             180 / std::numbers::pi;
    case TriggerSignal::add:
      return value_of(quantity.operands[0], world) + value_of(quantity.operands[1], world);
    case TriggerSignal::subtract:
      return value_of(quantity.operands[0], world) - value_of(quantity.operands[1], world);
    case TriggerSignal::multiply:
      return value_of(quantity.operands[0], world) * value_of(quantity.operands[1], world);
    case TriggerSignal::divide:
      return value_of(quantity.operands[0], world) / value_of(quantity.operands[1], world);
    case TriggerSignal::negate: return -value_of(quantity.operands[0], world);
  }
  return 0;
}

}  // namespace

std::optional<TriggerCondition> compile_trigger(const Formula& formula, const TriggerNames& names,
                                                Diagnostics& diagnostics) {
  return Compiler(names, diagnostics).formula(formula);
}

bool trigger_holds(const TriggerCondition& condition, const WorldSnapshot& world) {
  switch (condition.kind) {
    case TriggerKind::comparison: {
      double a = value_of(condition.sides[0], world);
      double b = value_of(condition.sides[1], world);
      switch (condition.compare) {
        case CompareOp::less: return a < b;
        case CompareOp::less_equal: return a <= b;
        case CompareOp::greater: return a > b;
        case CompareOp::greater_equal: return a >= b;
        case CompareOp::equal: return a == b;
        case CompareOp::not_equal: return a != b;
      }
      return false;
    }
    case TriggerKind::truth: return value_of(condition.sides[0], world) != 0;
    case TriggerKind::negation: return !trigger_holds(condition.operands[0], world);
    case TriggerKind::conjunction:
      return trigger_holds(condition.operands[0], world) &&
             trigger_holds(condition.operands[1], world);
    case TriggerKind::disjunction:
      return trigger_holds(condition.operands[0], world) ||
             trigger_holds(condition.operands[1], world);
    case TriggerKind::implication:
      return !trigger_holds(condition.operands[0], world) ||
             trigger_holds(condition.operands[1], world);
  }
  return false;
}

double lateral_offset(const KinematicState& a, const KinematicState& b) {
  return -(a.x - b.x) * std::sin(b.heading) + (a.y - b.y) * std::cos(b.heading);
}

double longitudinal_offset(const KinematicState& a, const KinematicState& b) {
  return (a.x - b.x) * std::cos(b.heading) + (a.y - b.y) * std::sin(b.heading);
}

RelativeSector relative_sector(const KinematicState& a, double a_length, const KinematicState& b,
                               double b_length) {
  const double along = longitudinal_offset(a, b);
  const double across = lateral_offset(a, b);
  const bool beside = std::abs(along) <= (a_length + b_length) / 2;
  if (across > kInLineLateral) {
    if (beside) return RelativeSector::SL;
    return along > 0 ? RelativeSector::FSL : RelativeSector::RSL;
  }
  if (across < -kInLineLateral) {
    if (beside) return RelativeSector::SR;
    return along > 0 ? RelativeSector::FSR : RelativeSector::RSR;
  }
  return along >= 0 ? RelativeSector::F : RelativeSector::R;
}

std::optional<RelativeSector> relative_sector_named(std::string_view word) {
  std::string upper;
  for (char c : word) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (std::size_t i = 0; i < kSectorNames.size(); ++i)
    if (upper == kSectorNames[i]) return static_cast<RelativeSector>(i);
  return std::nullopt;
}

}  // namespace scenfuzz
