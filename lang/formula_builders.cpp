// Spec term and formula builders (formula_builders.hpp).
#include "lang/formula_builders.hpp"

namespace scenfuzz {

SpecTerm signal_term(const char* name, SourceLocation at, std::vector<SpecTerm> operands) {
  SpecTerm term;
  term.kind = TermKind::signal;
  term.name = name;
  term.operands = std::move(operands);
  term.location = at;
  return term;
}

SpecTerm word_term(std::string word, SourceLocation at) {
  SpecTerm term;
  term.kind = TermKind::word;
  term.name = std::move(word);
  term.location = at;
  return term;
}

SpecTerm number_term(double value, SourceLocation at) {
  return value_term(constant_value(value, at), at);
}

SpecTerm value_term(Value value, SourceLocation at) {
  SpecTerm term;
  term.kind = TermKind::number;
  term.value = std::move(value);
  term.location = at;
  return term;
}

SpecTerm product_term(SpecTerm a, SpecTerm b, SourceLocation at) {
  SpecTerm term;
  term.kind = TermKind::multiply;
  term.operands = {std::move(a), std::move(b)};
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

}  // namespace scenfuzz
