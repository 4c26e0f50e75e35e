// The `.acc` lexer: one pass over the text with a TextCursor, so that every token knows its line
// and column (UTF-8 characters count one column each).
#include "lang/accident/lexer.hpp"

#include <charconv>
#include <cmath>

#include "lang/text_cursor.hpp"

namespace scenfuzz::accident {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_word_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_word_char(char c) { return is_word_start(c) || is_digit(c); }
bool is_exponent(char c) { return c == 'e' || c == 'E'; }

class Lexer : TextCursor {
 public:
  Lexer(const SourceFile& file, Diagnostics& diagnostics)
      : TextCursor(file.text()), diagnostics_(diagnostics) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    while (true) {
      skip_blanks_and_comments();
      if (at_end()) break;
      tokens.push_back(next());
    }
    Token end;
    end.location = here();
    tokens.push_back(end);
    return tokens;
  }

 private:
  void skip_blanks_and_comments() {
    while (!at_end()) {
      if (is_blank(peek()) || at_line_break()) {
        advance();
      } else if (peek() == '#' || (peek() == '/' && peek(1) == '/')) {
        while (!at_end() && !at_line_break()) advance();
      } else {
        return;
      }
    }
  }

  Token next() {
    const char c = peek();
    if (is_word_start(c)) return word();
    if (starts_number()) return number();
    switch (c) {
      case '=': return punctuation(TokenKind::equals);
      case ';': return punctuation(TokenKind::semicolon);
      case ',': return punctuation(TokenKind::comma);
      case '[': return punctuation(TokenKind::left_bracket);
      case ']': return punctuation(TokenKind::right_bracket);
      case '(': return punctuation(TokenKind::left_paren);
      case ')': return punctuation(TokenKind::right_paren);
      default: return bad_character();
    }
  }

  char peek_back() const { return pos_ > 0 ? text_[pos_ - 1] : '\0'; }

  bool starts_number() const {
    std::size_t at = (peek() == '-' || peek() == '+') ? 1 : 0;
    if (peek(at) == '.') ++at;
    return is_digit(peek(at));
  }

  // The token's text runs from `begin` to the cursor.
  Token finish(TokenKind kind, SourceLocation begin) {
    Token token;
    token.kind = kind;
    begin.length = static_cast<std::uint32_t>(pos_ - begin.offset);
    token.location = begin;
    token.text = std::string(text_.substr(begin.offset, begin.length));
    return token;
  }

  Token punctuation(TokenKind kind) {
    const SourceLocation begin = here();
    advance();
    return finish(kind, begin);
  }

  Token word() {
    const SourceLocation begin = here();
    while (!at_end() && is_word_char(peek())) advance();
    return finish(TokenKind::word, begin);
  }

  // [+-] digits [. digits] [e [+-] digits]; letters, digits or dots straight after it make the
  // whole run one malformed number (`1.2.3`, `12m`).
  Token number() {
    const SourceLocation begin = here();
    if (peek() == '-' || peek() == '+') advance();
    while (is_digit(peek())) advance();
    if (peek() == '.') advance();
    while (is_digit(peek())) advance();
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '-' || peek(1) == '+') && is_digit(peek(2))))) {
      advance(2);
      while (is_digit(peek())) advance();
    }
    bool malformed = false;
    while (!at_end() && (is_word_char(peek()) || peek() == '.' ||
                         ((peek() == '+' || peek() == '-') && is_exponent(peek_back())))) {
      malformed = true;
      advance();
    }
    Token token = finish(TokenKind::number, begin);
    if (malformed) return invalid(std::move(token), "'" + token.text + "' is not a number");
    std::string_view digits = token.text;
    if (digits.front() == '+') digits.remove_prefix(1);  // from_chars takes no '+'
    auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), token.number);
    if (error != std::errc() || end != digits.data() + digits.size() ||
        !std::isfinite(token.number))
      return invalid(std::move(token), "'" + token.text + "' is not a finite number");
    return token;
  }

  // One character, however many bytes it takes in UTF-8.
  Token bad_character() {
    const SourceLocation begin = here();
    advance();
    Token token = finish(TokenKind::invalid, begin);
    const unsigned char first = static_cast<unsigned char>(token.text.front());
    const bool printable = token.text.size() == 1 && first >= 0x21 && first < 0x7F;
    return invalid(std::move(token), printable ? "unexpected character '" + token.text + "'"
                                               : "unexpected character");
  }

  Token invalid(Token token, std::string message) {
    diagnostics_.error(token.location, std::move(message));
    token.kind = TokenKind::invalid;
    return token;
  }

  Diagnostics& diagnostics_;
};

}  // namespace

std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics) {
  return Lexer(file, diagnostics).run();
}

}  // namespace scenfuzz::accident
