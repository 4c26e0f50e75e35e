#include "lang/spec_horizon.hpp"

#include <algorithm>
#include <vector>

namespace scenfuzz {

namespace {

double operands_horizon(const Formula& formula) {
  double horizon = 0;
  for (const Formula& operand : formula.operands)
    horizon = std::max(horizon, formula_horizon(operand));
  return horizon;
}

}  // namespace

double formula_horizon(const Formula& formula) {
  const double inner = operands_horizon(formula);
  switch (formula.kind) {
    case FormulaKind::always:
    case FormulaKind::eventually:
    case FormulaKind::until:
      // A window ending in the past (upper < 0) still needs what its operand reads from there.
      if (formula.interval) return std::max(0.0, formula.interval->upper + inner);
      return inner;
    default: return inner;
  }
}

std::optional<SpecHorizon> longest_horizon(std::span<const Spec> specs) {
  std::optional<SpecHorizon> longest;
  for (const Spec& spec : specs) {
    const double horizon = formula_horizon(spec.formula);
    if (horizon > 0 && (!longest || horizon > longest->seconds)) longest = {spec.name, horizon};
  }
  return longest;
}

std::vector<SpecHorizon> horizons_beyond(std::span<const Spec> specs, double duration) {
  std::vector<SpecHorizon> beyond;
  for (const Spec& spec : specs)
    if (const double horizon = formula_horizon(spec.formula); horizon > duration)
      beyond.push_back({spec.name, horizon});
  return beyond;
}

}  // namespace scenfuzz
