// Specifications: STL formulas over the signals of a simulated trace.
//
// Terms are numeric signals (`dis(trace[ego], trace[truth][npc1])`, `speed`, `3.6 * x`);
// formulas compare terms and combine comparisons with boolean and temporal operators. Named
// signals are kept by name (`dis`, `trafficLightAhead.color`, `stoplineAhead`): the oracle gives
// them meaning, the front ends only check that they exist and are used with the right arguments.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/position.hpp"
#include "lang/value.hpp"

namespace scenfuzz {

enum class TermKind {
  number,       // `value`
  time_of_day,  // `value`, seconds since midnight, written `20:00`
  word,         // an enumeration word such as `green` or `left`, in `name`
  signal,       // named signal `name`, with `operands` as its arguments (possibly none)
  object,       // a trace projection: `source` of actor `name` (empty for the ego)
  column,       // a numeric column `name` (x, y, speed, ...) of operands[0], an object term
  position,     // a point on the map, in `position`
  vector,       // a vector (velocity, acceleration): two or three number terms (x, y[, z up])
  add,
  subtract,
  multiply,
  divide,
  power,
  negate,
};

enum class ObjectSource { ego, truth, perception };

struct SpecTerm {
  TermKind kind = TermKind::number;
  Value value;
  std::string name;
  ObjectSource source = ObjectSource::ego;
  std::vector<SpecTerm> operands;
  std::optional<Position> position;
  SourceLocation location;

  bool operator==(const SpecTerm&) const = default;
};

enum class CompareOp { less, less_equal, greater, greater_equal, equal, not_equal };

enum class FormulaKind {
  comparison,   // terms[0] compare terms[1]
  predicate,    // a boolean signal, terms[0] (e.g. `hornOn`, `stoplineAhead(2)`)
  negation,     // ~operands[0]
  conjunction,  // operands[0] & operands[1]
  disjunction,  // operands[0] | operands[1]
  implication,  // operands[0] -> operands[1]
  always,       // G[interval] operands[0]
  eventually,   // F[interval] operands[0]
  next,         // X operands[0]
  until,        // operands[0] U[interval] operands[1]
};

// Seconds relative to the current sample; the lower bound may be negative (looks into the past).
struct TimeInterval {
  double lower = 0.0;
  double upper = 0.0;

  bool operator==(const TimeInterval&) const = default;
};

struct Formula {
  FormulaKind kind = FormulaKind::predicate;
  CompareOp compare = CompareOp::less;
  std::vector<SpecTerm> terms;
  std::vector<Formula> operands;
  std::optional<TimeInterval> interval;  // none: the rest of the trace
  SourceLocation location;

  bool operator==(const Formula&) const = default;
};

struct Spec {
  std::string name;   // the formula's variable name when it had one, else "spec<N>"
  std::string trace;  // the trace variable it is asserted on
  Formula formula;
  SourceLocation location;

  bool operator==(const Spec&) const = default;
};

}  // namespace scenfuzz
