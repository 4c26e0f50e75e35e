// The specs of a scenario once some actors are gone, for tmin: every atom that reads a removed
// actor goes, and with it what cannot stand without it, so that a scenario whose spec names each
// NPC (LawBreaker's `G(dis1 >= 0.5 & dis2 >= 0.5 & ...)`) can still lose the NPCs its failure
// does not involve. Whether the failure is still the same is tmin's predicate's to say.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lang/spec.hpp"

namespace scenfuzz {

// `formula` without the atoms that read an actor in `removed`: a conjunction or disjunction keeps
// the operand that is left; an implication or until, and a negation or temporal operator, goes
// with its operand. Nullopt when nothing is left.
std::optional<Formula> formula_without_actors(const Formula& formula,
                                              const std::set<std::string>& removed);

// Every spec pruned so; a spec with nothing left goes.
std::vector<Spec> specs_without_actors(const std::vector<Spec>& specs,
                                       const std::set<std::string>& removed);

}  // namespace scenfuzz
