// The reference robustness: every operator by its textbook definition, sample by sample.
#include "tests/oracle/naive_robustness.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "lang/value.hpp"

namespace scenfuzz::test {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Terms are evaluated here too rather than through scenfuzz::term_signal, so that no engine code
// takes part in the values the engine is checked against.
SignalValues naive_term(const SpecTerm& term, const SignalSource& source) {
  const std::size_t samples = source.time.size();
  SignalValues result;
  switch (term.kind) {
    case TermKind::number:
    case TermKind::time_of_day:
      result.values.assign(samples, evaluate(term.value, source.parameters));
      return result;
    case TermKind::word: {
      double code = 0;
      if (term.name == "red" || term.name == "left")
        code = 1;
      else if (term.name == "yellow" || term.name == "right")
        code = 2;
      else if (term.name == "green")
        code = 3;
      else if (term.name != "off" && term.name != "forward")
        throw OracleError(term.location, "unknown word " + term.name);
      result.values.assign(samples, code);
      result.discrete = true;
      return result;
    }
    case TermKind::signal:
    case TermKind::column: {
      result = source.leaf(term);
      if (result.values.size() != samples)
        throw OracleError(term.location, term.name + " has the wrong number of samples");
      for (double value : result.values)
        if (!std::isfinite(value))
          throw OracleError(term.location, term.name + " has a value that is not a number");
      return result;
    }
    case TermKind::negate: {
      result = naive_term(term.operands.at(0), source);
      for (double& value : result.values) value = -value;
      result.discrete = false;
      return result;
    }
    case TermKind::add:
    case TermKind::subtract:
    case TermKind::multiply:
    case TermKind::divide:
    case TermKind::power: {
      const SignalValues left = naive_term(term.operands.at(0), source);
      const SignalValues right = naive_term(term.operands.at(1), source);
      result.values.resize(samples);
      for (std::size_t i = 0; i < samples; ++i) {
        const double a = left.values[i], b = right.values[i];
        switch (term.kind) {
          case TermKind::add: result.values[i] = a + b; break;
          case TermKind::subtract: result.values[i] = a - b; break;
          case TermKind::multiply: result.values[i] = a * b; break;
          case TermKind::divide: result.values[i] = a / b; break;
          default: result.values[i] = std::pow(a, b); break;
        }
      }
      return result;
    }
    case TermKind::object:
    case TermKind::position:
    case TermKind::vector: break;
  }
  throw OracleError(term.location, "not a numeric term");
}

double compare(CompareOp op, double a, double b, bool discrete) {
  if (discrete) {
    bool holds = false;
    switch (op) {
      case CompareOp::less: holds = a < b; break;
      case CompareOp::less_equal: holds = a <= b; break;
      case CompareOp::greater: holds = a > b; break;
      case CompareOp::greater_equal: holds = a >= b; break;
      case CompareOp::equal: holds = a == b; break;
      case CompareOp::not_equal: holds = a != b; break;
    }
    return holds ? 1.0 : -1.0;
  }
  switch (op) {
    case CompareOp::less:
    case CompareOp::less_equal: return b - a;
    case CompareOp::greater:
    case CompareOp::greater_equal: return a - b;
    case CompareOp::equal: return -std::abs(a - b);
    case CompareOp::not_equal: return std::abs(a - b);
  }
  return 0;
}

// Whether sample j lies in the window of sample i.
bool in_window(const Formula& formula, const SignalSource& source, std::size_t i, std::size_t j) {
  if (!formula.interval) return j >= i;
  const double offset = source.time[j] - source.time[i];
  return offset >= formula.interval->lower - kWindowTolerance &&
         offset <= formula.interval->upper + kWindowTolerance;
}

}  // namespace

std::vector<double> naive_robustness(const Formula& formula, const SignalSource& source) {
  const std::size_t samples = source.time.size();
  std::vector<double> result(samples);
  switch (formula.kind) {
    case FormulaKind::comparison: {
      const SignalValues left = naive_term(formula.terms.at(0), source);
      const SignalValues right = naive_term(formula.terms.at(1), source);
      const bool discrete = left.discrete && right.discrete;
      for (std::size_t i = 0; i < samples; ++i)
        result[i] = compare(formula.compare, left.values[i], right.values[i], discrete);
      return result;
    }
    case FormulaKind::predicate: {
      const SpecTerm& term = formula.terms.at(0);
      const SignalValues value = naive_term(term, source);
      if (term.operands.size() == 1) {
        const SignalValues distance = naive_term(term.operands[0], source);
        for (std::size_t i = 0; i < samples; ++i) result[i] = distance.values[i] - value.values[i];
      } else {
        for (std::size_t i = 0; i < samples; ++i) result[i] = value.values[i] != 0 ? 1.0 : -1.0;
      }
      return result;
    }
    case FormulaKind::negation: {
      result = naive_robustness(formula.operands.at(0), source);
      for (double& value : result) value = -value;
      return result;
    }
    case FormulaKind::conjunction:
    case FormulaKind::disjunction:
    case FormulaKind::implication: {
      const std::vector<double> left = naive_robustness(formula.operands.at(0), source);
      const std::vector<double> right = naive_robustness(formula.operands.at(1), source);
      for (std::size_t i = 0; i < samples; ++i) {
        if (formula.kind == FormulaKind::conjunction)
          result[i] = std::min(left[i], right[i]);
        else if (formula.kind == FormulaKind::disjunction)
          result[i] = std::max(left[i], right[i]);
        else
          result[i] = std::max(-left[i], right[i]);
      }
      return result;
    }
    case FormulaKind::always:
    case FormulaKind::eventually: {
      const std::vector<double> operand = naive_robustness(formula.operands.at(0), source);
      const bool always = formula.kind == FormulaKind::always;
      for (std::size_t i = 0; i < samples; ++i) {
        double value = always ? kInfinity : -kInfinity;
        for (std::size_t j = 0; j < samples; ++j)
          if (in_window(formula, source, i, j))
            value = always ? std::min(value, operand[j]) : std::max(value, operand[j]);
        result[i] = value;
      }
      return result;
    }
    case FormulaKind::next: {
      const std::vector<double> operand = naive_robustness(formula.operands.at(0), source);
      for (std::size_t i = 0; i < samples; ++i)
        result[i] = i + 1 < samples ? operand[i + 1] : kInfinity;
      return result;
    }
    case FormulaKind::until: {
      const std::vector<double> holding = naive_robustness(formula.operands.at(0), source);
      const std::vector<double> reached = naive_robustness(formula.operands.at(1), source);
      for (std::size_t i = 0; i < samples; ++i) {
        double value = -kInfinity;
        // min of `holding` over [i, j): +inf while j <= i.
        double holding_so_far = kInfinity;
        for (std::size_t j = 0; j < samples; ++j) {
          if (j > i) holding_so_far = std::min(holding_so_far, holding[j - 1]);
          if (in_window(formula, source, i, j))
            value = std::max(value, std::min(reached[j], holding_so_far));
        }
        result[i] = value;
      }
      return result;
    }
  }
  return result;
}

}  // namespace scenfuzz::test
