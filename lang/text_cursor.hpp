// Walking through a file's text one byte at a time while keeping its line and column, as every
// front end's lexer does: the shared half of the lexer layer (DESIGN.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "lang/line_break.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz {

inline bool is_continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Invariant: line_ and column_ are those of the byte at pos_ (columns count UTF-8 characters).
class TextCursor {
 public:
  explicit TextCursor(std::string_view text) : text_(text) {}

 protected:
  bool at_end() const { return pos_ >= text_.size(); }
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
  }

  SourceLocation here() const { return {line_, column_, static_cast<std::uint32_t>(pos_), 0}; }

  // At LF, CR or CRLF: what ends a line, whatever the file's line endings.
  bool at_line_break() const { return !at_end() && is_line_break_byte(text_[pos_]); }

  // Moves past one character; a CRLF line break is one character.
  void advance() {
    if (std::size_t width = line_break_width(text_, pos_)) {
      pos_ += width;
      ++line_;
      column_ = 1;
      return;
    }
    ++pos_;
    // Columns count characters: a UTF-8 continuation byte does not start a new one.
    if (pos_ >= text_.size() || !is_continuation_byte(text_[pos_])) ++column_;
  }

  // Moves past n characters (none of the callers spans a line break, so n is also bytes).
  void advance(std::size_t n) {
    for (std::size_t i = 0; i < n && !at_end(); ++i) advance();
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint32_t line_ = 1;
  std::uint32_t column_ = 1;
};

}  // namespace scenfuzz
