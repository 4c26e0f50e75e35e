// The specification module of a CH-Scenario file, after its `ConstraintList` header: safety
// protocols of the whole list, and constraints (`NAME relate with A, B`) with their safety
// protocols and events (`event: when GUARD do ACTION`, or an event's guard and action on their
// own `guard:` and `action:` lines, as the grammar's example writes them), each with a
// probability.
#pragma once

#include <string>

#include "lang/chs/lines.hpp"
#include "lang/chs/syntax.hpp"
#include "lang/chs/values.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::chs {

class ConstraintReader {
 public:
  ConstraintReader(File& file, Diagnostics& diagnostics) : file_(file), diagnostics_(diagnostics) {}

  // A constraint's first line (`constraint1 relate with forward_vehicle, current_vehicle`,
  // optionally after the word `constraint`): true when `line` is one.
  bool read_start(const Line& line);
  // A `key: value` line of the list; false when the key is not one of its keys.
  bool read_field(const std::string& key, SourceLocation key_at, const Value& value);
  // Every event has its guard and action.
  void finish();

 private:
  Event* event_for(bool is_guard, SourceLocation key_at);
  void read_event(SourceLocation key_at, const Value& value);

  File& file_;
  Diagnostics& diagnostics_;
  // The last event's halves still to come on `guard:` and `action:` lines, and whether its
  // probability was given.
  bool guard_pending_ = false, action_pending_ = false, probability_given_ = false;
};

}  // namespace scenfuzz::chs
