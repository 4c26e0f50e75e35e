// Splits WMG SDL level-2 text into tokens. `#` starts a comment that runs to the end of the line;
// strings are single-quoted (straight or typographic quotes).
#pragma once

#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/syntax_values.hpp"
#include "lang/wmg/token.hpp"

namespace scenfuzz::wmg {

// Always ends with an end_of_file token. Bad characters are reported and become invalid tokens.
std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics);

// The digits [begin, begin + count) of a token as a whole number with their own location: the
// two parts of a version `1.0`, which the lexer reads as one number.
WholeNumber digits_of(const Token& token, std::size_t begin, std::size_t count);

}  // namespace scenfuzz::wmg
