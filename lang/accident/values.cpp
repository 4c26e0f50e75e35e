// Reading property values from the token cursor.
#include "lang/accident/values.hpp"

#include <cmath>

namespace scenfuzz::accident {

namespace {

bool expect_equals(TokenCursor& cursor, const Token& keyword) {
  if (cursor.at(TokenKind::equals)) {
    cursor.take();
    return true;
  }
  cursor.fail("'=' after " + upper(keyword.text));
  return false;
}

// `expected` says what the name is for in the message.
std::optional<Name> read_name(TokenCursor& cursor, const std::string& expected) {
  if (!cursor.at(TokenKind::word)) {
    cursor.fail(expected);
    return std::nullopt;
  }
  const Token& token = cursor.take();
  return Name{token.text, token.location};
}

bool is_non_finite_word(const std::string& text) {
  const std::string word = lower(text);
  return word == "nan" || word == "inf" || word == "infinity";
}

// One coordinate; `axis` is "x" or "y".
std::optional<std::pair<double, SourceLocation>> read_coordinate(TokenCursor& cursor,
                                                                 const std::string& axis) {
  if (cursor.at(TokenKind::word) && is_non_finite_word(cursor.peek().text)) {
    cursor.error(cursor.peek().location,
                 "coordinates are finite numbers, not '" + cursor.peek().text + "'");
    cursor.skip_item();
    return std::nullopt;
  }
  if (!cursor.at(TokenKind::number)) {
    cursor.fail("the " + axis + " coordinate, a number of metres");
    return std::nullopt;
  }
  const Token& token = cursor.take();
  if (std::abs(token.number) > kCoordinateLimit)
    cursor.error(token.location,
                 "the " + axis + " coordinate must be from -100000 to 100000 m, not " + token.text);
  return std::pair{token.number, token.location};
}

// `( x , y )`.
std::optional<Point> read_point(TokenCursor& cursor) {
  if (!cursor.at(TokenKind::left_paren)) {
    cursor.fail("'(' to start the coordinates, such as (0, -12.5)");
    return std::nullopt;
  }
  const SourceLocation open = cursor.take().location;
  const std::size_t errors = cursor.diagnostics().error_count();
  auto x = read_coordinate(cursor, "x");
  if (!x) return std::nullopt;
  if (!cursor.at(TokenKind::comma)) {
    cursor.fail("',' between the x and y coordinates");
    return std::nullopt;
  }
  cursor.take();
  auto y = read_coordinate(cursor, "y");
  if (!y) return std::nullopt;
  if (!cursor.at(TokenKind::right_paren)) {
    cursor.fail("')' to close the coordinates");
    return std::nullopt;
  }
  cursor.take();
  if (cursor.diagnostics().error_count() != errors) return std::nullopt;  // out of range
  return Point{x->first, y->first, span(open, cursor.last()), x->second, y->second};
}

std::optional<std::size_t> read_choice(TokenCursor& cursor, std::string_view what,
                                       std::span<const std::string_view> spellings) {
  std::string list;
  for (std::size_t i = 0; i < spellings.size(); ++i)
    list += std::string(i == 0                      ? ""
                        : i + 1 == spellings.size() ? " or "
                                                    : ", ") +
            std::string(spellings[i]);
  if (!cursor.at(TokenKind::word)) {
    cursor.fail("a " + std::string(what) + " (" + list + ")");
    return std::nullopt;
  }
  const Token& token = cursor.peek();
  const std::string written = lower(token.text);
  for (std::size_t i = 0; i < spellings.size(); ++i)
    if (written == spellings[i]) {
      cursor.take();
      return i;
    }
  std::string message = "unknown " + std::string(what) + " '" + token.text + "'";
  if (auto best = nearest(token.text, spellings))
    message += "; did you mean '" + *best + "'?";
  else
    message += ": expected " + list;
  cursor.error(token.location, message);
  cursor.skip_item();
  return std::nullopt;
}

}  // namespace

std::optional<Name> read_name_property(TokenCursor& cursor, const Token& keyword,
                                       const std::string& what) {
  if (!expect_equals(cursor, keyword)) return std::nullopt;
  std::optional<Name> name = read_name(cursor, what + " (a name of letters, digits and '_')");
  if (name) cursor.end_property(what);
  return name;
}

std::optional<Point> read_point_property(TokenCursor& cursor, const Token& keyword) {
  if (!expect_equals(cursor, keyword)) return std::nullopt;
  std::optional<Point> point = read_point(cursor);
  if (point || cursor.at(TokenKind::semicolon)) cursor.end_property("the coordinates");
  return point;
}

std::optional<std::size_t> read_choice_property(TokenCursor& cursor, const Token& keyword,
                                                std::string_view what,
                                                std::span<const std::string_view> spellings) {
  if (!expect_equals(cursor, keyword)) return std::nullopt;
  std::optional<std::size_t> index = read_choice(cursor, what, spellings);
  if (index) cursor.end_property("the " + std::string(what));
  return index;
}

std::optional<Involvement> read_involvement_property(TokenCursor& cursor, const Token& keyword) {
  if (!expect_equals(cursor, keyword)) return std::nullopt;
  const std::string who = lower(keyword.text) == "actor" ? "the actor" : "the victim";
  std::optional<Name> id = read_name(cursor, who + "'s ID");
  if (!id) return std::nullopt;
  if (!cursor.at(TokenKind::comma)) {
    cursor.fail("',' and the part of " + who +
                " that was hit (front, rear, leftside, rightside or unknown)");
    return std::nullopt;
  }
  cursor.take();
  const Choices<Part> choices = parts();
  std::vector<std::string_view> spellings;
  for (const auto& value : choices.values) spellings.push_back(value.first);
  const SourceLocation part_at = cursor.peek().location;
  std::optional<std::size_t> index = read_choice(cursor, choices.what, spellings);
  if (!index) return std::nullopt;
  cursor.end_property(who);
  return Involvement{*id, {choices.values[*index].second, part_at}, span(id->location, part_at)};
}

std::optional<SignReference> read_sign_property(TokenCursor& cursor, const Token& keyword) {
  if (!expect_equals(cursor, keyword)) return std::nullopt;
  const std::string what = lower(keyword.text) == "startsign" ? "the start sign" : "the end sign";
  SignReference sign;
  if (cursor.at(TokenKind::left_paren)) {
    std::optional<Point> point = read_point(cursor);
    if (!point) return std::nullopt;
    sign.kind = SignReference::Kind::point;
    sign.point = *point;
    sign.location = point->location;
  } else {
    std::optional<Name> name =
        read_name(cursor, what + " (a LIGHT's or TREE's ID, or a place (x, y))");
    if (!name) return std::nullopt;
    sign.name = *name;
    sign.location = name->location;
  }
  cursor.end_property(what);
  return sign;
}

}  // namespace scenfuzz::accident
