// CH-Scenario safety protocols as specs (translation.hpp; docs/ch-scenario.md, "Safety
// protocols"): each predicate must hold throughout the run, `G (predicate)`, over the ego's
// signals. A name is a condition (wiper, lighton, hazardlighton, emergencybreak) or a number
// (dist, safedistance, speed); comparing a condition with true or false is the condition or its
// negation.
#include <algorithm>
#include <array>
#include <variant>

#include "lang/chs/translation.hpp"
#include "lang/chs/vocabulary.hpp"

namespace scenfuzz::chs {

namespace {

// What a piece of a predicate is: a condition, a number-valued signal, or true/false.
struct Truth {
  bool value = false;
};
using Meaning = std::variant<Formula, SpecTerm, Truth>;

SpecTerm signal_term(const char* name, SourceLocation at) {
  SpecTerm term;
  term.kind = TermKind::signal;
  term.name = name;
  term.location = at;
  return term;
}

SpecTerm number_term(double value, SourceLocation at) {
  SpecTerm term;
  term.kind = TermKind::number;
  term.value = constant_value(value, at);
  term.location = at;
  return term;
}

Formula comparison(CompareOp op, SpecTerm a, SpecTerm b, SourceLocation at) {
  Formula formula;
  formula.kind = FormulaKind::comparison;
  formula.compare = op;
  formula.terms = {std::move(a), std::move(b)};
  formula.location = at;
  return formula;
}

Formula flag_on(const char* signal, SourceLocation at) {
  return comparison(CompareOp::equal, signal_term(signal, at), number_term(1, at), at);
}

Formula combined(FormulaKind kind, Formula a, Formula b, SourceLocation at) {
  Formula formula;
  formula.kind = kind;
  formula.operands = {std::move(a), std::move(b)};
  formula.location = at;
  return formula;
}

Formula negated(Formula a, SourceLocation at) {
  Formula formula;
  formula.kind = FormulaKind::negation;
  formula.operands = {std::move(a)};
  formula.location = at;
  return formula;
}

// The share of full braking above which the ego brakes in an emergency (law signal `brake`).
constexpr double kEmergencyBrake = 70;
// The safe distance: what the ego drives in this many seconds (the two-second rule).
constexpr double kSafeSeconds = 2;

std::string joined_words(const std::string& name) {
  std::string joined;
  for (const std::string& word : words_of(name)) joined += word;
  return joined;
}

std::optional<Meaning> named(const std::string& name, SourceLocation at) {
  const std::string key = joined_words(name);
  if (key == "wiper" || key == "wipers" || key == "wiperon") return flag_on("wiperOn", at);
  if (key == "lighton" || key == "lightson" || key == "headlighton" || key == "headlightson")
    return combined(FormulaKind::disjunction, flag_on("lowBeamOn", at), flag_on("highBeamOn", at),
                    at);
  if (key == "hazardlighton" || key == "hazardlightson" || key == "hazardlight")
    return flag_on("warningFlashOn", at);
  if (key == "foglighton" || key == "foglightson") return flag_on("fogLightOn", at);
  if (key == "hornon" || key == "horn") return flag_on("hornOn", at);
  if (key == "emergencybreak" || key == "emergencybrake" || key == "emergencybraking")
    return comparison(CompareOp::greater, signal_term("brake", at),
                      number_term(kEmergencyBrake, at), at);
  if (key == "dist" || key == "distance") return signal_term("NPCAhead", at);
  if (key == "speed") return signal_term("speed", at);  // km/h, as the file's speeds
  if (key == "safedistance") {
    SpecTerm term;
    term.kind = TermKind::multiply;
    term.operands = {signal_term("speed", at), number_term(kSafeSeconds / 3.6, at)};
    term.location = at;
    return term;
  }
  return std::nullopt;
}

constexpr const char* kNames =
    "wiper, lighton, hazardlighton, foglighton, hornon, emergencybreak, dist, safedistance, speed";

CompareOp compare_op(const std::string& op) {
  if (op == "==") return CompareOp::equal;
  if (op == "!=") return CompareOp::not_equal;
  if (op == "<") return CompareOp::less;
  if (op == "<=") return CompareOp::less_equal;
  if (op == ">") return CompareOp::greater;
  return CompareOp::greater_equal;
}

class PredicateTranslator {
 public:
  explicit PredicateTranslator(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

  std::optional<Meaning> meaning(const Expression& e) {
    switch (e.kind) {
      case Expression::Kind::name: {
        auto found = named(e.text, e.location);
        if (!found)
          diagnostics_.error(e.location, "scenfuzz knows no signal '" + e.text +
                                             "' of a safety protocol; it knows " + kNames);
        return found;
      }
      case Expression::Kind::number: return number_term(e.number, e.location);
      case Expression::Kind::boolean: return Truth{e.boolean};
      case Expression::Kind::negation: {
        auto operand = meaning(e.operands[0]);
        if (!operand) return std::nullopt;
        if (auto* truth = std::get_if<Truth>(&*operand)) return Truth{!truth->value};
        auto formula = condition(*operand, e.operands[0].location);
        if (!formula) return std::nullopt;
        return negated(std::move(*formula), e.location);
      }
      case Expression::Kind::binary: return binary(e);
    }
    return std::nullopt;
  }

  // The meaning as a condition (true and false have none: a protocol of a constant is pointless).
  std::optional<Formula> condition(Meaning& m, SourceLocation at) {
    if (auto* formula = std::get_if<Formula>(&m)) return std::move(*formula);
    diagnostics_.error(at, std::holds_alternative<Truth>(m)
                               ? "a constant true or false here decides nothing about the run"
                               : "this is a number, where a condition is expected: compare it");
    return std::nullopt;
  }

 private:
  std::optional<Meaning> binary(const Expression& e) {
    auto a = meaning(e.operands[0]);
    auto b = meaning(e.operands[1]);
    if (!a || !b) return std::nullopt;
    if (e.text == "&&" || e.text == "||") return logical(e, *a, *b);
    auto* truth_a = std::get_if<Truth>(&*a);
    auto* truth_b = std::get_if<Truth>(&*b);
    if (truth_a || truth_b)
      return against_truth(e, truth_a ? *b : *a, truth_a ? *truth_a : *truth_b);
    auto* term_a = std::get_if<SpecTerm>(&*a);
    auto* term_b = std::get_if<SpecTerm>(&*b);
    if (!term_a || !term_b) {
      diagnostics_.error(e.location,
                         "compare a condition with true or false, and numbers with "
                         "numbers");
      return std::nullopt;
    }
    return comparison(compare_op(e.text), std::move(*term_a), std::move(*term_b), e.location);
  }

  std::optional<Meaning> logical(const Expression& e, Meaning& a, Meaning& b) {
    const bool conjunction = e.text == "&&";
    // true && x is x, false || x is x; the other way round the whole is constant.
    for (auto [truth, other] : {std::pair{&a, &b}, std::pair{&b, &a}})
      if (auto* t = std::get_if<Truth>(truth)) {
        if (t->value != conjunction) return Truth{t->value};
        return std::move(*other);
      }
    auto fa = condition(a, e.operands[0].location);
    auto fb = condition(b, e.operands[1].location);
    if (!fa || !fb) return std::nullopt;
    return combined(conjunction ? FormulaKind::conjunction : FormulaKind::disjunction,
                    std::move(*fa), std::move(*fb), e.location);
  }

  // `x = true`, `x != false`, `(a > b) = false`: the condition or its negation.
  std::optional<Meaning> against_truth(const Expression& e, Meaning& other, Truth truth) {
    if (e.text != "==" && e.text != "!=") {
      diagnostics_.error(e.location, "true and false are compared with = or != only");
      return std::nullopt;
    }
    if (auto* t = std::get_if<Truth>(&other))
      return Truth{(t->value == truth.value) == (e.text == "==")};
    auto formula = condition(other, e.location);
    if (!formula) return std::nullopt;
    if (truth.value == (e.text == "==")) return std::move(*formula);
    return negated(std::move(*formula), e.location);
  }

  Diagnostics& diagnostics_;
};

void add_protocol(Translation& translation, const Expression& predicate, const std::string& name) {
  PredicateTranslator translator(translation.diagnostics);
  auto meaning = translator.meaning(predicate);
  if (!meaning) return;
  auto condition = translator.condition(*meaning, predicate.location);
  if (!condition) return;
  Formula always;
  always.kind = FormulaKind::always;
  always.operands = {std::move(*condition)};
  always.location = predicate.location;
  translation.scenario.specs.push_back(
      {name, translation.scenario.trace_name, std::move(always), predicate.location});
}

// The names a constraint may relate with besides the file's entities: the ego, the vehicle ahead
// of it and the road's edge.
constexpr std::array<std::string_view, 7> kRelatable{
    "ego", "currentvehicle", "forwardvehicle", "edge", "road", "roadedge", "frontvehicle"};

void check_related(Translation& translation, const Constraint& constraint) {
  for (const Text& related : constraint.related) {
    const std::string key = joined_words(related.text);
    bool known = std::find(kRelatable.begin(), kRelatable.end(), key) != kRelatable.end();
    for (const auto& e : translation.file.dynamic_entities) known |= e.name.text == related.text;
    for (const auto& e : translation.file.static_entities) known |= e.name.text == related.text;
    if (!known)
      translation.diagnostics.warning(related.location,
                                      "'" + related.text +
                                          "' is no entity of the file, nor the "
                                          "ego, the forward vehicle or the road edge");
  }
}

std::string numbered(const std::string& name, std::size_t i, std::size_t count) {
  return count == 1 ? name : name + std::to_string(i + 1);
}

}  // namespace

void translate_specs(Translation& translation) {
  const File& file = translation.file;
  for (std::size_t i = 0; i < file.safety_protocols.size(); ++i)
    add_protocol(translation, file.safety_protocols[i],
                 numbered("safety_protocol", i, file.safety_protocols.size()));
  for (const Constraint& constraint : file.constraints) {
    check_related(translation, constraint);
    const std::size_t count = constraint.safety_protocols.size();
    for (std::size_t i = 0; i < count; ++i)
      add_protocol(translation, constraint.safety_protocols[i],
                   numbered(constraint.name.text + ".safety_protocol", i, count));
    for (const Event& event : constraint.events)
      translation.diagnostics.warning(event.location,
                                      "scenfuzz does not simulate events yet: "
                                      "this one is left out");
  }
}

}  // namespace scenfuzz::chs
