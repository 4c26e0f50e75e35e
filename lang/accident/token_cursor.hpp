// Walking through a `.acc` file's tokens: looking ahead, taking, describing what was found for a
// message, and getting back on track after a mistake (at the end of the property, the `]` of its
// bracket or the next keyword), so that independent mistakes are all reported.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lang/accident/lexer.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::accident {

class TokenCursor {
 public:
  TokenCursor(std::vector<Token> tokens, Diagnostics& diagnostics);

  // The token `ahead` places on (the end_of_file token past the end).
  const Token& peek(std::size_t ahead = 0) const;
  bool at(TokenKind kind) const { return peek().kind == kind; }
  // A keyword starting a property or an object: a word followed by `=` or `[`.
  bool at_item_start() const;
  const Token& take();
  // Where the last token taken ends: a span's end.
  const SourceLocation& last() const { return last_; }

  // "'KIND'", "the end of the file": the next token in a message.
  std::string found() const;
  void error(SourceLocation where, std::string message);
  // "expected EXPECTED, found ..." at the next token, and the rest of the item skipped. Nothing is
  // reported at a token the lexer already reported.
  void fail(const std::string& expected);
  // Takes the `;` that ends a property, or reports it missing after `what` ("the kind"). When the
  // next token starts another property or closes the bracket, nothing more is skipped.
  void end_property(const std::string& what);
  // Skips to the end of the current item: past the next `;` or the bracket opened in it, or up
  // to (not past) the `]` that closes the enclosing bracket or a keyword starting the next item.
  void skip_item();

  Diagnostics& diagnostics() { return diagnostics_; }
  bool too_many_errors() const { return diagnostics_.too_many_errors(); }

 private:
  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  SourceLocation last_;
  Diagnostics& diagnostics_;
};

}  // namespace scenfuzz::accident
