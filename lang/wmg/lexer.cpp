#include "lang/wmg/lexer.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "lang/text_cursor.hpp"

namespace scenfuzz::wmg {

std::string describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::end_of_file: return "end of file";
    case TokenKind::word: return "a word";
    case TokenKind::number: return "a number";
    case TokenKind::string: return "a string";
    case TokenKind::left_bracket: return "'['";
    case TokenKind::right_bracket: return "']'";
    case TokenKind::left_paren: return "'('";
    case TokenKind::right_paren: return "')'";
    case TokenKind::left_brace: return "'{'";
    case TokenKind::right_brace: return "'}'";
    case TokenKind::colon: return "':'";
    case TokenKind::comma: return "','";
    case TokenKind::dot: return "'.'";
    case TokenKind::arrow: return "'->'";
    case TokenKind::plus: return "'+'";
    case TokenKind::minus: return "'-'";
    case TokenKind::slash: return "'/'";
    case TokenKind::assign: return "'='";
    case TokenKind::less: return "'<'";
    case TokenKind::less_equal: return "'<='";
    case TokenKind::greater: return "'>'";
    case TokenKind::greater_equal: return "'>='";
    case TokenKind::equal: return "'=='";
    case TokenKind::not_equal: return "'!='";
    case TokenKind::invalid: return "an invalid token";
  }
  return "a token";
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::word: return "'" + token.text + "'";
    case TokenKind::number: return "number '" + token.text + "'";
    case TokenKind::string: return "string '" + token.text + "'";
    default: return describe(token.kind);
  }
}

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

// Typographic single quotes are three UTF-8 bytes: E2 80 98 (opening) and E2 80 99 (closing).
std::size_t single_quote_width(std::string_view text, std::size_t i) {
  if (text[i] == '\'') return 1;
  if (i + 2 < text.size() && static_cast<unsigned char>(text[i]) == 0xE2 &&
      static_cast<unsigned char>(text[i + 1]) == 0x80) {
    auto third = static_cast<unsigned char>(text[i + 2]);
    if (third == 0x98 || third == 0x99) return 3;
  }
  return 0;
}

class Lexer : private TextCursor {
 public:
  Lexer(const SourceFile& file, Diagnostics& diagnostics)
      : TextCursor(file.text()), diagnostics_(diagnostics) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    while (true) {
      skip_space_and_comments();
      if (at_end()) break;
      tokens.push_back(next());
    }
    Token end;
    end.kind = TokenKind::end_of_file;
    end.location = here();
    tokens.push_back(end);
    return tokens;
  }

 private:
  void skip_space_and_comments() {
    while (!at_end()) {
      char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '#') {
        while (!at_end() && !at_line_break()) advance();
      } else if (static_cast<unsigned char>(c) == 0xEF && peek(1) == '\xBB' && peek(2) == '\xBF') {
        advance(3);  // UTF-8 byte order mark
      } else {
        return;
      }
    }
  }

  Token make(TokenKind kind, SourceLocation start) const {
    Token token;
    token.kind = kind;
    start.length = static_cast<std::uint32_t>(pos_ - start.offset);
    token.location = start;
    token.text = std::string(text_.substr(start.offset, start.length));
    return token;
  }

  Token invalid(SourceLocation start, const std::string& message) {
    Token bad = make(TokenKind::invalid, start);
    diagnostics_.error(bad.location, message);
    return bad;
  }

  Token next() {
    SourceLocation start = here();
    char c = peek();
    if (single_quote_width(text_, pos_) > 0) return string_literal();
    if (c == '"') return double_quoted_string();
    if (is_digit(c)) return number();
    if (is_letter(c)) {
      while (!at_end() && (is_letter(peek()) || is_digit(peek()))) advance();
      return make(TokenKind::word, start);
    }
    auto single = [&](TokenKind kind, std::size_t width = 1) {
      advance(width);
      return make(kind, start);
    };
    switch (c) {
      case '[': return single(TokenKind::left_bracket);
      case ']': return single(TokenKind::right_bracket);
      case '(': return single(TokenKind::left_paren);
      case ')': return single(TokenKind::right_paren);
      case '{': return single(TokenKind::left_brace);
      case '}': return single(TokenKind::right_brace);
      case ':': return single(TokenKind::colon);
      case ',': return single(TokenKind::comma);
      case '+': return single(TokenKind::plus);
      case '/': return single(TokenKind::slash);
      case '-': return peek(1) == '>' ? single(TokenKind::arrow, 2) : single(TokenKind::minus);
      case '<': return peek(1) == '=' ? single(TokenKind::less_equal, 2) : single(TokenKind::less);
      case '>':
        return peek(1) == '=' ? single(TokenKind::greater_equal, 2) : single(TokenKind::greater);
      case '=': return peek(1) == '=' ? single(TokenKind::equal, 2) : single(TokenKind::assign);
      case '!':
        if (peek(1) == '=') return single(TokenKind::not_equal, 2);
        break;
      case '.':
        if (is_digit(peek(1))) {
          advance();
          while (is_digit(peek())) advance();
          std::string digits(text_.substr(start.offset + 1, pos_ - start.offset - 1));
          return invalid(
              start, "a number needs a digit before its decimal point (write 0." + digits + ")");
        }
        return single(TokenKind::dot);
      default: break;
    }
    // Report the whole (possibly multi-byte) character once.
    advance();
    while (!at_end() && is_continuation_byte(peek())) advance();
    Token bad = make(TokenKind::invalid, start);
    diagnostics_.error(bad.location, "unexpected character '" + bad.text + "'");
    return bad;
  }

  Token string_literal() {
    SourceLocation start = here();
    advance(single_quote_width(text_, pos_));
    std::size_t content_begin = pos_;
    while (!at_end() && !at_line_break()) {
      std::size_t close_width = single_quote_width(text_, pos_);
      if (close_width > 0) {
        std::string contents(text_.substr(content_begin, pos_ - content_begin));
        advance(close_width);
        Token token = make(TokenKind::string, start);
        token.text = std::move(contents);
        return token;
      }
      advance();
    }
    Token bad = make(TokenKind::invalid, start);
    bad.location.length = static_cast<std::uint32_t>(content_begin - start.offset);
    diagnostics_.error(bad.location,
                       "unterminated string: expected a closing ' before the end of the line");
    return bad;
  }

  // A string in double quotes is one mistake, reported once: the whole quoted text is skipped.
  Token double_quoted_string() {
    SourceLocation start = here();
    advance();
    while (!at_end() && !at_line_break() && peek() != '"') advance();
    if (!at_end() && peek() == '"') advance();
    return invalid(start, "strings are written in single quotes: 'text'");
  }

  // DOUBLE is [-]INT[.INT]: no exponent, no unit, no leading or trailing decimal point.
  Token number() {
    SourceLocation start = here();
    while (is_digit(peek())) advance();
    if (peek() == '.' && is_digit(peek(1))) {
      advance();
      while (is_digit(peek())) advance();
    } else if (peek() == '.' && !is_letter(peek(1))) {
      advance();
      return invalid(start, "expected digits after the decimal point");
    }
    if (is_letter(peek())) {
      while (is_letter(peek()) || is_digit(peek())) advance();
      Token bad = make(TokenKind::invalid, start);
      diagnostics_.error(bad.location, "'" + bad.text +
                                           "' is not a number: write plain decimals such as 20.5 "
                                           "(no exponent, no unit)");
      return bad;
    }
    Token token = make(TokenKind::number, start);
    auto [end, error] =
        std::from_chars(token.text.data(), token.text.data() + token.text.size(), token.number);
    // 0.000...01 with hundreds of zeros underflows: too small to represent, as good as zero.
    std::string whole_part = token.text.substr(0, token.text.find('.'));
    bool underflow = error == std::errc::result_out_of_range &&
                     whole_part.find_first_not_of('0') == std::string::npos;
    if (underflow) {
      token.number = 0.0;
    } else if (error != std::errc() || !std::isfinite(token.number)) {
      diagnostics_.error(token.location, "number '" + token.text + "' is out of range");
      token.kind = TokenKind::invalid;
      token.number = 0.0;
    }
    return token;
  }

  Diagnostics& diagnostics_;
};

}  // namespace

std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics) {
  return Lexer(file, diagnostics).run();
}

WholeNumber digits_of(const Token& token, std::size_t begin, std::size_t count) {
  WholeNumber part;
  std::from_chars(token.text.data() + begin, token.text.data() + begin + count, part.value);
  part.location = token.location;
  part.location.offset += static_cast<std::uint32_t>(begin);
  part.location.column += static_cast<std::uint32_t>(begin);
  part.location.length = static_cast<std::uint32_t>(count);
  return part;
}

}  // namespace scenfuzz::wmg
