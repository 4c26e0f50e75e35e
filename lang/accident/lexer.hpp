// Splits a `.acc` file into tokens: words (keywords, values and IDs alike), numbers and the
// punctuation `= ; , [ ] ( )`. White space and line breaks mean nothing; `//` and `#` start a
// comment to the end of the line (the CarSim paper's template output heads its parts with
// `// Static Objects` lines). A character or number that cannot be read is reported here, once,
// and left as an `invalid` token that the parser skips silently.
#pragma once

#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz::accident {

enum class TokenKind {
  end_of_file,
  word,  // letters, digits and underscores, not starting with a digit
  number,
  equals,
  semicolon,
  comma,
  left_bracket,   // [
  right_bracket,  // ]
  left_paren,     // (
  right_paren,    // )
  invalid,        // already reported
};

struct Token {
  TokenKind kind = TokenKind::end_of_file;
  std::string text;  // as written
  double number = 0;
  SourceLocation location;
};

// All of a file's tokens; the last is always end_of_file, located just after the text.
std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::accident
