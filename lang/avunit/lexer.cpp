#include "lang/avunit/lexer.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "lang/text_cursor.hpp"

namespace scenfuzz::avunit {

std::string describe(TokenKind kind) {
  switch (kind) {
    case TokenKind::end_of_file: return "end of file";
    case TokenKind::identifier: return "an identifier";
    case TokenKind::number: return "a number";
    case TokenKind::string: return "a string";
    case TokenKind::time: return "a time of day";
    case TokenKind::left_paren: return "'('";
    case TokenKind::right_paren: return "')'";
    case TokenKind::left_brace: return "'{'";
    case TokenKind::right_brace: return "'}'";
    case TokenKind::left_bracket: return "'['";
    case TokenKind::right_bracket: return "']'";
    case TokenKind::comma: return "','";
    case TokenKind::semicolon: return "';'";
    case TokenKind::colon: return "':'";
    case TokenKind::dot: return "'.'";
    case TokenKind::assign: return "'='";
    case TokenKind::satisfies: return "'|='";
    case TokenKind::arrow: return "'->'";
    case TokenKind::plus: return "'+'";
    case TokenKind::minus: return "'-'";
    case TokenKind::star: return "'*'";
    case TokenKind::slash: return "'/'";
    case TokenKind::caret: return "'^'";
    case TokenKind::dot_plus: return "'.+'";
    case TokenKind::dot_minus: return "'.-'";
    case TokenKind::dot_star: return "'.*'";
    case TokenKind::dot_slash: return "'./'";
    case TokenKind::less: return "'<'";
    case TokenKind::less_equal: return "'<='";
    case TokenKind::greater: return "'>'";
    case TokenKind::greater_equal: return "'>='";
    case TokenKind::equal: return "'=='";
    case TokenKind::not_equal: return "'!='";
    case TokenKind::tilde: return "'~'";
    case TokenKind::ampersand: return "'&'";
    case TokenKind::bar: return "'|'";
    case TokenKind::invalid: return "an invalid token";
  }
  return "a token";
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::end_of_file: return "end of file";
    case TokenKind::identifier: return "'" + token.text + "'";
    case TokenKind::number: return "number '" + token.text + "'";
    case TokenKind::string: return "string \"" + token.text + "\"";
    case TokenKind::time: return "time '" + token.text + "'";
    default: return describe(token.kind);
  }
}

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

// Typographic quotes are three UTF-8 bytes: E2 80 98/99 (single) and E2 80 9C/9D (double).
enum class Quote { none, single, double_ };

Quote quote_at(std::string_view text, std::size_t i, std::size_t& width) {
  if (text[i] == '"') return width = 1, Quote::double_;
  if (text[i] == '\'') return width = 1, Quote::single;
  if (i + 2 < text.size() && static_cast<unsigned char>(text[i]) == 0xE2 &&
      static_cast<unsigned char>(text[i + 1]) == 0x80) {
    auto third = static_cast<unsigned char>(text[i + 2]);
    width = 3;
    if (third == 0x98 || third == 0x99) return Quote::single;
    if (third == 0x9C || third == 0x9D) return Quote::double_;
  }
  return Quote::none;
}

}  // namespace

class Lexer : private TextCursor {
 public:
  Lexer(const SourceFile& file, Diagnostics& diagnostics)
      : TextCursor(file.text()), diagnostics_(diagnostics) {}

  Token next_token() {
    while (true) {
      skip_space_and_comments();
      if (at_end()) break;
      if (std::optional<Token> token = next()) return std::move(*token);
    }
    Token end;
    end.kind = TokenKind::end_of_file;
    end.location = here();
    return end;
  }

 private:
  void skip_space_and_comments() {
    while (!at_end()) {
      char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else if ((c == '/' && peek(1) == '/') || c == '#') {
        while (!at_end() && !at_line_break()) advance();
      } else if (c == '/' && peek(1) == '*') {
        SourceLocation start = here();
        advance(2);
        while (!at_end() && !(peek() == '*' && peek(1) == '/')) advance();
        if (at_end()) {
          start.length = 2;
          diagnostics_.error(start, "unterminated comment: expected '*/' before the end of file");
        } else {
          advance(2);
        }
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

  std::optional<Token> next() {
    SourceLocation start = here();
    char c = peek();
    std::size_t quote_width = 0;
    if (quote_at(text_, pos_, quote_width) != Quote::none) return string_literal();
    if (is_digit(c)) return number_or_time();
    if (is_letter(c)) {
      while (!at_end() && (is_letter(peek()) || is_digit(peek()))) advance();
      return make(TokenKind::identifier, start);
    }
    auto single = [&](TokenKind kind, std::size_t width = 1) {
      advance(width);
      return make(kind, start);
    };
    switch (c) {
      case '(': return single(TokenKind::left_paren);
      case ')': return single(TokenKind::right_paren);
      case '{': return single(TokenKind::left_brace);
      case '}': return single(TokenKind::right_brace);
      case '[': return single(TokenKind::left_bracket);
      case ']': return single(TokenKind::right_bracket);
      case ',': return single(TokenKind::comma);
      case ';': return single(TokenKind::semicolon);
      case ':': return single(TokenKind::colon);
      case '+': return single(TokenKind::plus);
      case '*': return single(TokenKind::star);
      case '/': return single(TokenKind::slash);
      case '^': return single(TokenKind::caret);
      case '~': return single(TokenKind::tilde);
      case '&': return single(TokenKind::ampersand);
      case '-': return peek(1) == '>' ? single(TokenKind::arrow, 2) : single(TokenKind::minus);
      case '|': return peek(1) == '=' ? single(TokenKind::satisfies, 2) : single(TokenKind::bar);
      case '<': return peek(1) == '=' ? single(TokenKind::less_equal, 2) : single(TokenKind::less);
      case '>':
        return peek(1) == '=' ? single(TokenKind::greater_equal, 2) : single(TokenKind::greater);
      case '=': return peek(1) == '=' ? single(TokenKind::equal, 2) : single(TokenKind::assign);
      case '!':
        if (peek(1) == '=') return single(TokenKind::not_equal, 2);
        break;
      case '.':
        switch (peek(1)) {
          case '+': return single(TokenKind::dot_plus, 2);
          case '-': return single(TokenKind::dot_minus, 2);
          case '*': return single(TokenKind::dot_star, 2);
          case '/': return single(TokenKind::dot_slash, 2);
          default: break;
        }
        if (is_digit(peek(1))) {
          advance();
          while (is_digit(peek())) advance();
          Token number = make(TokenKind::number, start);
          number.number = std::stod("0" + number.text);
          diagnostics_.error(
              number.location,
              "a number needs a digit before its decimal point (write 0" + number.text + ")");
          return number;
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

  std::optional<Token> string_literal() {
    SourceLocation start = here();
    std::size_t width = 0;
    Quote open = quote_at(text_, pos_, width);
    advance(width);
    std::size_t content_begin = pos_;
    while (!at_end() && !at_line_break()) {
      std::size_t close_width = 0;
      if (quote_at(text_, pos_, close_width) == open) {
        Token token = make(TokenKind::string, start);
        token.text = std::string(text_.substr(content_begin, pos_ - content_begin));
        advance(close_width);
        token.location.length = static_cast<std::uint32_t>(pos_ - start.offset);
        return token;
      }
      advance();
    }
    Token bad = make(TokenKind::invalid, start);
    bad.location.length = static_cast<std::uint32_t>(width);
    diagnostics_.error(bad.location,
                       "unterminated string: expected a closing quote before the "
                       "end of the line");
    return bad;
  }

  std::size_t digits_at(std::size_t from) const {
    std::size_t n = 0;
    while (from + n < text_.size() && is_digit(text_[from + n])) ++n;
    return n;
  }

  // H:MM and H:MM:SS are times of day; `[0:10]` in an interval lexes as one too and the parser
  // splits it. A number followed by ':' and not exactly two digits stays a number.
  std::optional<Token> number_or_time() {
    SourceLocation start = here();
    std::size_t hour_digits = digits_at(pos_);
    std::size_t after = pos_ + hour_digits;
    auto two_digits_then_stop = [&](std::size_t at) {
      return at < text_.size() && text_[at] == ':' && digits_at(at + 1) == 2 &&
             !(at + 3 < text_.size() && text_[at + 3] == '.');
    };
    if (hour_digits <= 2 && two_digits_then_stop(after)) {
      int hour = std::stoi(std::string(text_.substr(pos_, hour_digits)));
      int minute = std::stoi(std::string(text_.substr(after + 1, 2)));
      int second = 0;
      std::size_t end = after + 3;
      if (two_digits_then_stop(end)) {
        second = std::stoi(std::string(text_.substr(end + 1, 2)));
        end += 3;
      }
      advance(end - pos_);
      Token token = make(TokenKind::time, start);
      token.number = hour * 3600.0 + minute * 60.0 + second;
      token.invalid_time =
          hour > 24 || minute > 59 || second > 59 || (hour == 24 && (minute || second));
      return token;
    }
    advance(hour_digits);
    if (peek() == '.' && is_digit(peek(1))) {
      advance();
      while (is_digit(peek())) advance();
    } else if (peek() == '.' && !is_letter(peek(1)) && peek(1) != '+' && peek(1) != '-' &&
               peek(1) != '*' && peek(1) != '/') {
      advance();
      Token number = make(TokenKind::number, start);
      number.number = std::stod(number.text.substr(0, number.text.size() - 1));
      diagnostics_.error(number.location, "expected digits after the decimal point");
      return number;
    }
    if ((peek() == 'e' || peek() == 'E') &&
        (is_digit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && is_digit(peek(2))))) {
      advance(2);
      while (is_digit(peek())) advance();
    }
    Token token = make(TokenKind::number, start);
    auto [end, error] =
        std::from_chars(token.text.data(), token.text.data() + token.text.size(), token.number);
    bool underflow =
        error == std::errc::result_out_of_range &&
        (token.text.find("e-") != std::string::npos || token.text.find("E-") != std::string::npos);
    if (underflow) {
      token.number = 0.0;  // too small to represent: as good as zero
    } else if (error != std::errc() || !std::isfinite(token.number)) {
      diagnostics_.error(token.location, "number '" + token.text + "' is out of range");
      token.number = 0.0;
    }
    return token;
  }

  Diagnostics& diagnostics_;
};

TokenReader::TokenReader(const SourceFile& file, Diagnostics& diagnostics)
    : lexer_(std::make_unique<Lexer>(file, diagnostics)) {}

TokenReader::~TokenReader() = default;

Token TokenReader::next() { return lexer_->next_token(); }

std::vector<Token> tokenize(const SourceFile& file, Diagnostics& diagnostics) {
  TokenReader reader(file, diagnostics);
  std::vector<Token> tokens;
  do {
    tokens.push_back(reader.next());
  } while (tokens.back().kind != TokenKind::end_of_file);
  return tokens;
}

}  // namespace scenfuzz::avunit
