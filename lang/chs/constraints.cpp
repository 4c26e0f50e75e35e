// Reading CH-Scenario's constraint list a line at a time.
#include "lang/chs/constraints.hpp"

#include "lang/chs/expressions.hpp"

namespace scenfuzz::chs {

bool ConstraintReader::read_start(const Line& line) {
  const std::size_t relate = line.text.find("relate with");
  if (relate == std::string_view::npos ||
      line.text.substr(0, relate).find(':') != std::string_view::npos)
    return false;
  std::string_view head = trimmed(line.text.substr(0, relate));
  std::size_t head_begin = static_cast<std::size_t>(head.data() - line.text.data());
  if (head.starts_with("constraint ")) {
    head = trimmed(head.substr(11));
    head_begin = static_cast<std::size_t>(head.data() - line.text.data());
  }
  Constraint constraint;
  constraint.location = line.whole();
  if (head.empty() || head.find(' ') != std::string_view::npos)
    diagnostics_.error(line.at(0, relate), "expected the constraint's name before 'relate with'");
  else
    constraint.name = {std::string(head), line.at(head_begin, head.size())};
  std::size_t at = relate + 11;
  while (at <= line.text.size()) {
    std::size_t comma = line.text.find(',', at);
    if (comma == std::string_view::npos) comma = line.text.size();
    const std::string_view entity = trimmed(line.text.substr(at, comma - at));
    const std::size_t begin =
        entity.empty() ? at : static_cast<std::size_t>(entity.data() - line.text.data());
    // A bad name is reported and left out: the constraint's lines below still belong to it.
    if (entity.empty() || entity.find(' ') != std::string_view::npos)
      diagnostics_.error(line.at(begin, entity.size()),
                         "expected an entity's name after 'relate with' (names separated by ',')");
    else
      constraint.related.push_back({std::string(entity), line.at(begin, entity.size())});
    at = comma + 1;
  }
  finish();
  file_.constraints.push_back(std::move(constraint));
  guard_pending_ = action_pending_ = probability_given_ = false;
  return true;
}

bool ConstraintReader::read_field(const std::string& key, SourceLocation key_at,
                                  const Value& value) {
  Constraint* constraint = file_.constraints.empty() ? nullptr : &file_.constraints.back();
  if (key == "safetyprotocol") {
    if (auto predicate = read_predicate(value, diagnostics_))
      (constraint ? constraint->safety_protocols : file_.safety_protocols).push_back(*predicate);
    return true;
  }
  if (key == "event") {
    read_event(key_at, value);
    return true;
  }
  if (key == "guard") {
    if (Event* event = event_for(true, key_at)) {
      if (auto guard = read_predicate(value, diagnostics_)) event->guard = *guard;
      guard_pending_ = false;
    }
    return true;
  }
  if (key == "action") {
    if (Event* event = event_for(false, key_at)) {
      if (auto action = read_action(value, diagnostics_)) event->action = *action;
      action_pending_ = false;
    }
    return true;
  }
  if (key == "probability") {
    if (constraint == nullptr || constraint->events.empty()) {
      diagnostics_.error(key_at, "a probability belongs to an event: write it after the event");
      return true;
    }
    if (probability_given_) {
      diagnostics_.error(key_at, "this event's probability is given twice");
      return true;
    }
    probability_given_ = true;
    auto number = read_number(value, diagnostics_, "the probability");
    if (number && !(number->value >= 0 && number->value <= 1))
      diagnostics_.error(number->location, "the probability must be from 0 to 1");
    else if (number)
      constraint->events.back().probability = *number;
    return true;
  }
  return false;
}

// The event a `guard:` or `action:` line completes: the last one while that half is still to
// come, else a new one (whose other half must follow).
Event* ConstraintReader::event_for(bool is_guard, SourceLocation key_at) {
  if (file_.constraints.empty()) {
    diagnostics_.error(key_at, std::string(is_guard ? "a guard" : "an action") +
                                   " belongs to a constraint: start one with 'NAME relate with "
                                   "ENTITY'");
    return nullptr;
  }
  Constraint& constraint = file_.constraints.back();
  if (constraint.events.empty() || !(is_guard ? guard_pending_ : action_pending_)) {
    finish();
    Event event;
    event.location = key_at;
    constraint.events.push_back(event);
    guard_pending_ = !is_guard;
    action_pending_ = is_guard;
    probability_given_ = false;
  }
  return &constraint.events.back();
}

void ConstraintReader::read_event(SourceLocation key_at, const Value& value) {
  if (file_.constraints.empty()) {
    diagnostics_.error(key_at,
                       "an event belongs to a constraint: start one with 'NAME relate "
                       "with ENTITY'");
    return;
  }
  auto text = chs::read_event(value, diagnostics_);
  if (!text) return;
  finish();
  Event event;
  event.location = span(key_at, value.location());
  if (text->guard) event.guard = *text->guard;
  if (text->action) event.action = *text->action;
  file_.constraints.back().events.push_back(std::move(event));
  guard_pending_ = text->guard_below;
  action_pending_ = text->action_below;
  probability_given_ = false;
}

void ConstraintReader::finish() {
  if (file_.constraints.empty() || file_.constraints.back().events.empty()) return;
  const Event& event = file_.constraints.back().events.back();
  if (guard_pending_)
    diagnostics_.error(event.location, "this event's guard is never given: add 'guard: ...'");
  if (action_pending_)
    diagnostics_.error(event.location, "this event's action is never given: add 'action: ...'");
  guard_pending_ = action_pending_ = false;
}

}  // namespace scenfuzz::chs
