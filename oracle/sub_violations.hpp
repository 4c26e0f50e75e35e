// LawBreaker's sub-violations of a spec (../shared/reference/scenest-law-signals.md, section 3):
// neg(phi), the list of formulas each of which, satisfied by a trace, is one way of violating phi
// (their disjunction is the negation of phi), built syntactically from its companion pos(phi).
// The 13-law Chinese specification has 81. Behaviour coverage counts the ones a run reaches.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "lang/spec.hpp"

namespace scenfuzz {

// More than this many sub-violations (they multiply along | and ->) is not expanded.
inline constexpr std::size_t kMaxSubViolations = 512;

// neg(formula) in LawBreaker's order; nullopt when there would be more than kMaxSubViolations.
std::optional<std::vector<Formula>> sub_violations(const Formula& formula);

}  // namespace scenfuzz
