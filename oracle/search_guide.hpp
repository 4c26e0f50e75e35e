// What a search minimises for a spec whose formula is a conjunction. A spec's robustness is the
// minimum over its conjuncts, so one conjunct that never changes (a parked van the ego always
// passes 1.27 m from) hides how close the others come: the search sees a plateau. The guide
// keeps every conjunct's say while keeping the sign of the robustness, so a point is a
// violation exactly when its guide is negative (the arithmetic-geometric mean robustness of
// Mehdipour, Vasile and Belta, 2019, without its normalisation):
//   some conjunct negative: the mean of the conjuncts' negative parts;
//   otherwise: the geometric mean of (1 + robustness) minus 1.
#pragma once

#include <span>
#include <vector>

#include "lang/spec.hpp"

namespace scenfuzz {

// The top-level conjuncts of `formula`: nested conjunctions flattened, and an always over a
// conjunction split into an always per conjunct (G (a & b) has the robustness of G a & G b).
// A formula that is no conjunction is its only conjunct.
std::vector<Formula> top_level_conjuncts(const Formula& formula);

// The guide for conjuncts with robustness `conjuncts` (at least one). -inf when one is -inf;
// +inf ones (an empty window) leave the mean; +inf when all are.
double conjunct_guide(std::span<const double> conjuncts);

}  // namespace scenfuzz
