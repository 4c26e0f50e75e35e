// Walks each spec's formula for law-signal terms (flags, distance predicates, values) whose
// names law_signal does not compute.
#include "oracle/spec_judgeable.hpp"

#include <algorithm>

#include "lang/avunit/builtins.hpp"
#include "oracle/law_signals.hpp"

namespace scenfuzz {

namespace {

bool is_law_signal(const SpecTerm& term) {
  if (term.kind != TermKind::signal) return false;
  const avunit::SignalClass kind = avunit::signal_class(term.name);
  return kind == avunit::SignalClass::flag || kind == avunit::SignalClass::distance_predicate ||
         kind == avunit::SignalClass::value;
}

void collect_term(const Spec& spec, const SpecTerm& term, std::vector<UncomputedSignal>& found) {
  if (is_law_signal(term) && !law_signal_computed(term.name)) {
    const bool seen = std::any_of(found.begin(), found.end(), [&](const UncomputedSignal& known) {
      // SourceLocation's == ignores places (IR equality); compare offsets.
      return known.spec == spec.name && known.location.offset == term.location.offset;
    });
    if (!seen)
      found.push_back(
          {spec.name, term.name, term.location, uncomputed_law_signal_message(term.name)});
  }
  for (const SpecTerm& operand : term.operands) collect_term(spec, operand, found);
}

void collect_formula(const Spec& spec, const Formula& formula,
                     std::vector<UncomputedSignal>& found) {
  for (const SpecTerm& term : formula.terms) collect_term(spec, term, found);
  for (const Formula& operand : formula.operands) collect_formula(spec, operand, found);
}

}  // namespace

std::vector<UncomputedSignal> uncomputed_signals(const ScenarioTemplate& scenario) {
  std::vector<UncomputedSignal> found;
  for (const Spec& spec : scenario.specs) collect_formula(spec, spec.formula, found);
  return found;
}

}  // namespace scenfuzz
