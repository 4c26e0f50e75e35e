// Splits AVUnit / scenest text into tokens. Comments (`//`, `#`, `/* */`) and white space are
// skipped; straight and typographic quotes both delimit strings.
#pragma once

#include <memory>
#include <vector>

#include "lang/avunit/token.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::avunit {

class Lexer;

// Reads a file's tokens one at a time, so that a big file's tokens are never all held at once.
// Bad characters are reported and skipped. `file` must outlive the reader.
class TokenReader {
 public:
  TokenReader(const SourceFile& file, Diagnostics& diagnostics);
  ~TokenReader();
  TokenReader(const TokenReader&) = delete;
  TokenReader& operator=(const TokenReader&) = delete;

  // The next token; end_of_file at the end, and again on every later call.
  Token next();

 private:
  std::unique_ptr<Lexer> lexer_;
};

// All of a file's tokens. Always ends with an end_of_file token.
std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit
