// The values of the formalism's properties, each read after its keyword up to and including the
// `;` that ends it: `= name;`, `= (x, y);`, `= crossroad;` (a word of a closed list),
// `= car1, front;` (an actor or victim) and `= light1;` or `= (x, y);` (a start or end sign).
// Each mistake is a diagnostic at the token where it was found, with what was expected, and the
// rest of the property is skipped; nullopt then.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/accident/syntax.hpp"
#include "lang/accident/token_cursor.hpp"
#include "lang/accident/vocabulary.hpp"

namespace scenfuzz::accident {

// Coordinates are metres from the scene's centre; beyond this they are a slip of the keyboard.
inline constexpr double kCoordinateLimit = 100000;

// `what` names the value in messages: "the ID", "the coordinates".
std::optional<Name> read_name_property(TokenCursor& cursor, const Token& keyword,
                                       const std::string& what);
std::optional<Point> read_point_property(TokenCursor& cursor, const Token& keyword);
std::optional<Involvement> read_involvement_property(TokenCursor& cursor, const Token& keyword);
std::optional<SignReference> read_sign_property(TokenCursor& cursor, const Token& keyword);

// `= word;` where word is one of `spellings` (any case): its index.
std::optional<std::size_t> read_choice_property(TokenCursor& cursor, const Token& keyword,
                                                std::string_view what,
                                                std::span<const std::string_view> spellings);

template <typename Value>
std::optional<Word<Value>> read_word_property(TokenCursor& cursor, const Token& keyword,
                                              const Choices<Value>& choices) {
  std::vector<std::string_view> spellings;
  for (const auto& value : choices.values) spellings.push_back(value.first);
  const SourceLocation at = cursor.peek(1).location;  // after the `=`
  const std::optional<std::size_t> index =
      read_choice_property(cursor, keyword, choices.what, spellings);
  if (!index) return std::nullopt;
  return Word<Value>{choices.values[*index].second, at};
}

}  // namespace scenfuzz::accident
