// The tokens of WMG SDL level 2. Keywords are not tokens of their own: they are multi-word
// phrases ("Junction type", "Number of lanes") that the parser matches word by word, so the
// lexer only knows words, numbers, strings and punctuation.
#pragma once

#include <string>

#include "lang/source_location.hpp"

namespace scenfuzz::wmg {

enum class TokenKind {
  end_of_file,
  word,    // letters, digits and '_', starting with a letter or '_'
  number,  // digits with an optional '.digits'; a sign is a separate minus token
  string,  // text holds the contents without the quotes
  left_bracket,
  right_bracket,
  left_paren,
  right_paren,
  left_brace,
  right_brace,
  colon,
  comma,
  dot,
  arrow,  // ->
  plus,
  minus,
  slash,
  assign,  // =
  less,
  less_equal,
  greater,
  greater_equal,
  equal,      // ==
  not_equal,  // !=
  invalid,    // something the lexer already reported; the parser fails at it silently
};

struct Token {
  TokenKind kind = TokenKind::end_of_file;
  std::string text;     // as written (string: the contents)
  double number = 0.0;  // number
  SourceLocation location;
};

// How a token kind is named in messages: "']'", "a number".
std::string describe(TokenKind kind);
// How a particular token is named in messages: "'Roads'", "number '3.5'", "end of file".
std::string describe(const Token& token);

}  // namespace scenfuzz::wmg
