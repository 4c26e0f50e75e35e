// CH-Scenario predicates as formulas (predicates.hpp).
#include "lang/chs/predicates.hpp"

#include "lang/chs/vocabulary.hpp"

namespace scenfuzz::chs {

namespace {

CompareOp compare_op(const std::string& op) {
  if (op == "==") return CompareOp::equal;
  if (op == "!=") return CompareOp::not_equal;
  if (op == "<") return CompareOp::less;
  if (op == "<=") return CompareOp::less_equal;
  if (op == ">") return CompareOp::greater;
  return CompareOp::greater_equal;
}

}  // namespace

std::string joined_words(const std::string& name) {
  std::string joined;
  for (const std::string& word : words_of(name)) joined += word;
  return joined;
}

std::optional<Meaning> PredicateTranslator::meaning(const Expression& e) {
  switch (e.kind) {
    case Expression::Kind::name: return names_(e.text, e.location);
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

std::optional<Formula> PredicateTranslator::condition(Meaning& m, SourceLocation at) {
  if (auto* formula = std::get_if<Formula>(&m)) return std::move(*formula);
  diagnostics_.error(at, std::holds_alternative<Truth>(m)
                             ? "a constant true or false here decides nothing about the run"
                             : "this is a number, where a condition is expected: compare it");
  return std::nullopt;
}

std::optional<Meaning> PredicateTranslator::binary(const Expression& e) {
  auto a = meaning(e.operands[0]);
  auto b = meaning(e.operands[1]);
  if (!a || !b) return std::nullopt;
  if (e.text == "&&" || e.text == "||") return logical(e, *a, *b);
  auto* truth_a = std::get_if<Truth>(&*a);
  auto* truth_b = std::get_if<Truth>(&*b);
  if (truth_a || truth_b) return against_truth(e, truth_a ? *b : *a, truth_a ? *truth_a : *truth_b);
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

std::optional<Meaning> PredicateTranslator::logical(const Expression& e, Meaning& a, Meaning& b) {
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
  return combined(conjunction ? FormulaKind::conjunction : FormulaKind::disjunction, std::move(*fa),
                  std::move(*fb), e.location);
}

// `x = true`, `x != false`, `(a > b) = false`: the condition or its negation.
std::optional<Meaning> PredicateTranslator::against_truth(const Expression& e, Meaning& other,
                                                          Truth truth) {
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

std::optional<Formula> PredicateTranslator::translate(const Expression& predicate) {
  auto m = meaning(predicate);
  if (!m) return std::nullopt;
  return condition(*m, predicate.location);
}

}  // namespace scenfuzz::chs
