// neg and pos by LawBreaker's table (../shared/reference/scenest-law-signals.md, 3.1): atoms give
// one each, negation swaps the lists, temporal operators map over them, and the lists concatenate
// or multiply along the boolean operators. Until drops its interval, as LawBreaker does.
#include "oracle/sub_violations.hpp"

#include <utility>

#include "lang/demand.hpp"

namespace scenfuzz {
namespace {

using Formulas = std::vector<Formula>;

Formula unary(FormulaKind kind, Formula operand, std::optional<TimeInterval> interval,
              SourceLocation location) {
  Formula formula;
  formula.kind = kind;
  formula.interval = interval;
  formula.location = location;
  formula.operands.push_back(std::move(operand));
  return formula;
}

Formula binary(FormulaKind kind, Formula a, Formula b, SourceLocation location) {
  Formula formula;
  formula.kind = kind;
  formula.location = location;
  formula.operands.push_back(std::move(a));
  formula.operands.push_back(std::move(b));
  return formula;
}

bool too_many(std::size_t a, std::size_t b) {
  return a > kMaxSubViolations || b > kMaxSubViolations || a * b > kMaxSubViolations;
}

Formulas mapped(const Formulas& list, FormulaKind kind, const Formula& node) {
  Formulas out;
  for (const Formula& f : list) out.push_back(unary(kind, f, node.interval, node.location));
  return out;
}

Formulas concatenated(Formulas a, const Formulas& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::optional<Formulas> neg(const Formula& node);
std::optional<Formulas> pos(const Formula& node);

// The lists of an operand, or nullopt (too many) propagated.
using List = std::optional<Formulas>;
List checked(Formulas list) {
  if (list.size() > kMaxSubViolations) return std::nullopt;
  return list;
}

// a x b, each pair joined by `kind`; nullopt when there would be too many.
List pairs(const List& a, const List& b, FormulaKind kind, const Formula& node) {
  if (!a || !b || too_many(a->size(), b->size())) return std::nullopt;
  Formulas out;
  for (const Formula& x : *a)
    for (const Formula& y : *b) out.push_back(binary(kind, x, y, node.location));
  return out;
}

List joined(const List& a, const List& b) {
  if (!a || !b) return std::nullopt;
  return checked(concatenated(*a, *b));
}

// Temporal operators keep the size: each entry wrapped in `kind` with the node's interval.
List wrapped(const List& inner, FormulaKind kind, const Formula& node) {
  if (!inner) return std::nullopt;
  return mapped(*inner, kind, node);
}

FormulaKind dual(FormulaKind kind) {
  if (kind == FormulaKind::always) return FormulaKind::eventually;
  if (kind == FormulaKind::eventually) return FormulaKind::always;
  return kind;  // next
}

// Until's sub-violations: every n1 & n2, then every (p1 & n2) U (n1' & n2').
List until_neg(const Formula& node) {
  const Formula& a = node.operands[0];
  const Formula& b = node.operands[1];
  const List n1 = neg(a), n2 = neg(b);
  List first = pairs(n1, n2, FormulaKind::conjunction, node);
  List left = pairs(pos(a), n2, FormulaKind::conjunction, node);
  if (!first || !left) return std::nullopt;
  List second = pairs(left, first, FormulaKind::until, node);
  return joined(first, second);
}

bool is_atom(const Formula& node) {
  return node.kind == FormulaKind::comparison || node.kind == FormulaKind::predicate;
}

// Operators have their operands (lang/spec.hpp): one for ~ G F X, two for & | -> U.
void demand_operands(const Formula& node) {
  const bool unary_kind = node.kind == FormulaKind::negation || node.kind == FormulaKind::always ||
                          node.kind == FormulaKind::eventually || node.kind == FormulaKind::next;
  SCENFUZZ_DEMAND(node.operands.size() == (unary_kind ? 1u : 2u));
}

List neg(const Formula& node) {
  if (is_atom(node))
    return Formulas{unary(FormulaKind::negation, node, std::nullopt, node.location)};
  demand_operands(node);
  switch (node.kind) {
    case FormulaKind::negation: return pos(node.operands[0]);
    case FormulaKind::always:
    case FormulaKind::eventually:
    case FormulaKind::next: return wrapped(neg(node.operands[0]), dual(node.kind), node);
    case FormulaKind::conjunction: return joined(neg(node.operands[0]), neg(node.operands[1]));
    case FormulaKind::disjunction:
      return pairs(neg(node.operands[0]), neg(node.operands[1]), FormulaKind::conjunction, node);
    case FormulaKind::implication:
      return pairs(pos(node.operands[0]), neg(node.operands[1]), FormulaKind::conjunction, node);
    default: return until_neg(node);
  }
}

List pos(const Formula& node) {
  if (is_atom(node)) return Formulas{node};
  demand_operands(node);
  switch (node.kind) {
    case FormulaKind::negation: return neg(node.operands[0]);
    case FormulaKind::always:
    case FormulaKind::eventually:
    case FormulaKind::next: return wrapped(pos(node.operands[0]), node.kind, node);
    case FormulaKind::conjunction:
      return pairs(pos(node.operands[0]), pos(node.operands[1]), FormulaKind::conjunction, node);
    case FormulaKind::disjunction: return joined(pos(node.operands[0]), pos(node.operands[1]));
    case FormulaKind::implication: return joined(neg(node.operands[0]), pos(node.operands[1]));
    default: {
      Formula plain = node;  // Until's positive forms drop the interval too
      plain.interval.reset();
      return pairs(pos(node.operands[0]), pos(node.operands[1]), FormulaKind::until, plain);
    }
  }
}

}  // namespace

std::optional<std::vector<Formula>> sub_violations(const Formula& formula) { return neg(formula); }

}  // namespace scenfuzz
