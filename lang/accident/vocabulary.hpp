// The words of the accident formalism: which keywords each bracket takes, the lower-case values
// of each closed list (road kinds, colours, ...), and the nearest spelling of a misspelt one for
// "did you mean" suggestions. Keywords and values are matched without regard to case.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "lang/accident/syntax.hpp"

namespace scenfuzz::accident {

// Where a keyword stands: at the top of the file or in one kind of bracket.
enum class Context {
  file,
  statics,
  road,
  tree,
  light,
  crossing,
  stop_sign,
  dynamics,
  vehicle,
  chain,
  event,
  accident,
  collision
};

// The keywords a context takes, upper case, in the grammar's order.
std::span<const std::string_view> keywords_of(Context context);
bool takes(Context context, std::string_view keyword);
// Whether a keyword may be given more than once in its context: the objects of a list (TREE,
// VEHICLE, EVENT, ...), not the properties of one object (ID, KIND, CHAIN, ...).
bool repeatable(std::string_view keyword);
// Whether the keyword is one of the formalism's anywhere.
bool is_keyword(std::string_view keyword);
// "a VEHICLE", "the STATIC part": the context in messages.
std::string context_name(Context context);
// "ID, KIND, INITDIRECTION, STARTSIGN, ENDSIGN or CHAIN".
std::string keyword_list(Context context);

std::string upper(std::string_view text);
std::string lower(std::string_view text);

// The spelling among `candidates` nearest to `written` (compared in upper case), when near enough
// to be a slip of the keyboard.
std::optional<std::string> nearest(std::string_view written,
                                   std::span<const std::string_view> candidates);

// A closed list of values: its lower-case spellings in the grammar's order and what each means.
template <typename Value>
struct Choices {
  std::string_view what;  // "road kind"
  std::span<const std::pair<std::string_view, Value>> values;
};

Choices<RoadKind> road_kinds();
Choices<Colour> colours();
Choices<VehicleKind> vehicle_kinds();
Choices<Direction> directions();
Choices<EventKind> event_kinds();
Choices<Part> parts();

// The spelling of a value, as the printer writes it.
template <typename Value>
std::string_view spelling(const Choices<Value>& choices, Value value) {
  for (const auto& [text, v] : choices.values)
    if (v == value) return text;
  return choices.values.front().first;
}

}  // namespace scenfuzz::accident
