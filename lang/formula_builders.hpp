// Small builders of spec terms and formulas, for the front ends that translate a language's
// conditions (CH-Scenario's guards and protocols, the accident formalism's event timings) into the
// IR's formulas without a syntax of their own for them.
#pragma once

#include <string>
#include <vector>

#include "lang/spec.hpp"

namespace scenfuzz {

SpecTerm signal_term(const char* name, SourceLocation at, std::vector<SpecTerm> operands = {});
SpecTerm word_term(std::string word, SourceLocation at);
SpecTerm number_term(double value, SourceLocation at);
// A number the search chooses: the value may read parameters.
SpecTerm value_term(Value value, SourceLocation at);
SpecTerm product_term(SpecTerm a, SpecTerm b, SourceLocation at);
Formula comparison(CompareOp op, SpecTerm a, SpecTerm b, SourceLocation at);
Formula combined(FormulaKind kind, Formula a, Formula b, SourceLocation at);
Formula negated(Formula a, SourceLocation at);

}  // namespace scenfuzz
