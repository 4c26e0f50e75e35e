// formula_without_actors: a post-order walk that drops atoms naming a removed actor.
#include "fuzz/tmin_specs.hpp"

namespace scenfuzz {

namespace {

bool reads_removed(const SpecTerm& term, const std::set<std::string>& removed) {
  if (term.kind == TermKind::object && removed.contains(term.name)) return true;
  for (const SpecTerm& operand : term.operands)
    if (reads_removed(operand, removed)) return true;
  return false;
}

}  // namespace

std::optional<Formula> formula_without_actors(const Formula& formula,
                                              const std::set<std::string>& removed) {
  switch (formula.kind) {
    case FormulaKind::comparison:
    case FormulaKind::predicate:
      for (const SpecTerm& term : formula.terms)
        if (reads_removed(term, removed)) return std::nullopt;
      return formula;
    case FormulaKind::conjunction:
    case FormulaKind::disjunction: {
      std::optional<Formula> left = formula_without_actors(formula.operands[0], removed);
      std::optional<Formula> right = formula_without_actors(formula.operands[1], removed);
      if (!left || !right) return left ? left : right;
      Formula kept = formula;
      kept.operands = {std::move(*left), std::move(*right)};
      return kept;
    }
    default: {
      Formula kept = formula;
      for (Formula& operand : kept.operands) {
        std::optional<Formula> pruned = formula_without_actors(operand, removed);
        if (!pruned) return std::nullopt;
        operand = std::move(*pruned);
      }
      return kept;
    }
  }
}

std::vector<Spec> specs_without_actors(const std::vector<Spec>& specs,
                                       const std::set<std::string>& removed) {
  std::vector<Spec> kept;
  for (const Spec& spec : specs) {
    std::optional<Formula> formula = formula_without_actors(spec.formula, removed);
    if (!formula) continue;
    Spec pruned = spec;
    pruned.formula = std::move(*formula);
    kept.push_back(std::move(pruned));
  }
  return kept;
}

}  // namespace scenfuzz
