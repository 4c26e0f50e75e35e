// The tokens of AVUnit and scenest.
#pragma once

#include <string>

#include "lang/source_location.hpp"

namespace scenfuzz::avunit {

enum class TokenKind {
  end_of_file,
  identifier,
  number,
  string,  // text holds the contents without the quotes
  time,    // H:MM or H:MM:SS; number holds seconds since midnight
  left_paren,
  right_paren,
  left_brace,
  right_brace,
  left_bracket,
  right_bracket,
  comma,
  semicolon,
  colon,
  dot,
  assign,     // =
  satisfies,  // |=
  arrow,      // ->
  plus,
  minus,
  star,
  slash,
  caret,
  dot_plus,  // .+ .- .* ./ : scenest's element-wise operators, the same as + - * / on scalars
  dot_minus,
  dot_star,
  dot_slash,
  less,
  less_equal,
  greater,
  greater_equal,
  equal,
  not_equal,
  tilde,
  ampersand,
  bar,
  invalid,  // something the lexer already reported; the parser skips its statement silently
};

struct Token {
  TokenKind kind = TokenKind::end_of_file;
  std::string text;     // as written (string: the contents)
  double number = 0.0;  // number, time
  // time: not a valid time of day (25:00, 0:60). It is still one token, because in an interval
  // `[0:60]` it is two bounds; used as a value it is an error.
  bool invalid_time = false;
  SourceLocation location;
};

// How a token kind is named in messages: "';'", "a number", "an identifier".
std::string describe(TokenKind kind);
// How a particular token is named in messages: "'foo'", "number '3.5'", "end of file".
std::string describe(const Token& token);

}  // namespace scenfuzz::avunit
