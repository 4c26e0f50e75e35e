// CH-Scenario's predicates and actions, from the text after a key's colon: guards and safety
// protocols (`(wiper = true) && not (dist < safedistance)`) and action statements (`position++;
// parked = false`).
#pragma once

#include <optional>
#include <vector>

#include "lang/chs/syntax.hpp"
#include "lang/chs/values.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::chs {

// The whole rest of the line as one predicate.
std::optional<Expression> read_predicate(const Value& value, Diagnostics& diagnostics);

// Statements separated by `;` or `,`.
std::optional<std::vector<Statement>> read_action(const Value& value, Diagnostics& diagnostics);

// `when GUARD do ACTION` (the words `guard` and `action` alone stand for the constraint's own
// `guard:` and `action:` lines, as the grammar's example writes it): nullopt guard or action
// then.
struct EventText {
  std::optional<Expression> guard;
  std::optional<std::vector<Statement>> action;
  bool guard_below = false, action_below = false;
};
std::optional<EventText> read_event(const Value& value, Diagnostics& diagnostics);

}  // namespace scenfuzz::chs
