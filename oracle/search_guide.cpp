#include "oracle/search_guide.hpp"

#include <cmath>
#include <limits>

namespace scenfuzz {

namespace {

void collect_conjuncts(const Formula& formula, std::vector<Formula>& conjuncts) {
  if (formula.kind == FormulaKind::conjunction) {
    for (const Formula& operand : formula.operands) collect_conjuncts(operand, conjuncts);
    return;
  }
  if (formula.kind == FormulaKind::always &&
      formula.operands.front().kind == FormulaKind::conjunction) {
    std::vector<Formula> inner;
    collect_conjuncts(formula.operands.front(), inner);
    for (Formula& operand : inner) {
      Formula always = formula;
      always.operands = {std::move(operand)};
      conjuncts.push_back(std::move(always));
    }
    return;
  }
  conjuncts.push_back(formula);
}

}  // namespace

std::vector<Formula> top_level_conjuncts(const Formula& formula) {
  std::vector<Formula> conjuncts;
  collect_conjuncts(formula, conjuncts);
  return conjuncts;
}

double conjunct_guide(std::span<const double> conjuncts) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  double negative_sum = 0;
  double log_sum = 0;
  std::size_t finite = 0;
  bool violated = false;
  for (const double robustness : conjuncts) {
    if (robustness == -infinity) return -infinity;
    if (robustness == infinity) continue;
    ++finite;
    if (robustness < 0) {
      violated = true;
      negative_sum += robustness;
    } else {
      log_sum += std::log1p(robustness);
    }
  }
  if (violated) return negative_sum / static_cast<double>(conjuncts.size());
  if (finite == 0) return infinity;
  return std::expm1(log_sum / static_cast<double>(finite));
}

}  // namespace scenfuzz
