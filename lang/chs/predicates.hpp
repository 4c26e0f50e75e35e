// CH-Scenario predicates as formulas: a safety protocol and an event's guard are both written as
// names, numbers, true/false, comparisons, not, and, or. What a name means differs (a protocol
// speaks of the ego's signals, a guard of the road user its event moves), so the caller gives it;
// the rest is shared: comparing a condition with true or false is the condition or its negation,
// `true && x` is x, and a number where a condition is expected is an error.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "lang/chs/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/formula_builders.hpp"
#include "lang/spec.hpp"

namespace scenfuzz::chs {

// What a piece of a predicate is: a condition, a number-valued signal, or true/false.
struct Truth {
  bool value = false;
};
using Meaning = std::variant<Formula, SpecTerm, Truth>;

// The meaning of a name, or nullopt after the resolver has reported why it has none.
using NameMeaning = std::function<std::optional<Meaning>(const std::string& name, SourceLocation)>;

// "wiper_on", "Wiper On" -> "wiperon": names compare by their words, without case.
std::string joined_words(const std::string& name);

class PredicateTranslator {
 public:
  PredicateTranslator(Diagnostics& diagnostics, NameMeaning names)
      : diagnostics_(diagnostics), names_(std::move(names)) {}

  std::optional<Meaning> meaning(const Expression& e);
  // The meaning as a condition (true and false have none: a constant decides nothing).
  std::optional<Formula> condition(Meaning& m, SourceLocation at);
  // The whole predicate as a condition.
  std::optional<Formula> translate(const Expression& predicate);

 private:
  std::optional<Meaning> binary(const Expression& e);
  std::optional<Meaning> logical(const Expression& e, Meaning& a, Meaning& b);
  std::optional<Meaning> against_truth(const Expression& e, Meaning& other, Truth truth);

  Diagnostics& diagnostics_;
  NameMeaning names_;
};

}  // namespace scenfuzz::chs
