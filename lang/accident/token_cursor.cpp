// The token cursor and its recovery after a mistake.
#include "lang/accident/token_cursor.hpp"

#include <utility>

namespace scenfuzz::accident {

TokenCursor::TokenCursor(std::vector<Token> tokens, Diagnostics& diagnostics)
    : tokens_(std::move(tokens)), diagnostics_(diagnostics) {
  if (tokens_.empty() || tokens_.back().kind != TokenKind::end_of_file) tokens_.emplace_back();
}

const Token& TokenCursor::peek(std::size_t ahead) const {
  const std::size_t at = next_ + ahead;
  return at < tokens_.size() ? tokens_[at] : tokens_.back();
}

bool TokenCursor::at_item_start() const {
  if (!at(TokenKind::word)) return false;
  const TokenKind after = peek(1).kind;
  return after == TokenKind::equals || after == TokenKind::left_bracket;
}

const Token& TokenCursor::take() {
  const Token& token = peek();
  if (next_ + 1 < tokens_.size()) ++next_;
  last_ = token.location;
  return token;
}

std::string TokenCursor::found() const {
  if (at(TokenKind::end_of_file)) return "the end of the file";
  return "'" + peek().text + "'";
}

void TokenCursor::error(SourceLocation where, std::string message) {
  diagnostics_.error(where, std::move(message));
}

void TokenCursor::fail(const std::string& expected) {
  if (!at(TokenKind::invalid))
    error(peek().location, "expected " + expected + ", found " + found());
  skip_item();
}

void TokenCursor::end_property(const std::string& what) {
  if (at(TokenKind::semicolon)) {
    take();
    return;
  }
  if (!at(TokenKind::invalid))
    error(peek().location, "expected ';' after " + what + ", found " + found());
  if (at(TokenKind::right_bracket) || at_item_start()) return;
  skip_item();
}

void TokenCursor::skip_item() {
  int depth = 0;
  bool skipped = false;
  while (!at(TokenKind::end_of_file)) {
    const TokenKind kind = peek().kind;
    if (depth == 0 && skipped && at_item_start()) return;
    if (kind == TokenKind::right_bracket) {
      if (depth == 0) return;
      take();
      if (--depth == 0) return;
      continue;
    }
    take();
    skipped = true;
    if (kind == TokenKind::left_bracket) ++depth;
    if (kind == TokenKind::semicolon && depth == 0) return;
  }
}

}  // namespace scenfuzz::accident
