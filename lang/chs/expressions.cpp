// A small recursive-descent parser over one line's tokens: or < and < not < comparison <
// primary, as C orders them, with `and`, `or` and `not` as words too.
#include "lang/chs/expressions.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace scenfuzz::chs {

namespace {

struct Token {
  enum class Kind { name, number, symbol, end };
  Kind kind = Kind::end;
  std::string text;  // name: lower case for words; symbol: the operator
  double number = 0;
  std::size_t begin = 0, size = 0;  // bytes in the line
};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

class Reader {
 public:
  Reader(const Value& value, Diagnostics& diagnostics)
      : line_(value.line), diagnostics_(diagnostics) {
    tokenize(value.begin);
  }

  bool failed() const { return failed_; }
  const Token& peek() const { return tokens_[at_]; }
  bool at_end() const { return peek().kind == Token::Kind::end; }
  bool at_word(std::string_view word) const {
    return peek().kind == Token::Kind::name && lower(peek().text) == word;
  }
  bool at_symbol(std::string_view symbol) const {
    return peek().kind == Token::Kind::symbol && peek().text == symbol;
  }
  const Token& take() { return tokens_[at_ < tokens_.size() - 1 ? at_++ : at_]; }
  SourceLocation where(const Token& token) const { return line_.at(token.begin, token.size); }
  SourceLocation from(const Token& first) const {
    const Token& last = tokens_[at_ > 0 ? at_ - 1 : 0];
    return line_.at(first.begin, last.begin + last.size - first.begin);
  }

  void fail(const std::string& expected) {
    if (failed_) return;
    failed_ = true;
    const Token& token = peek();
    const std::string found =
        token.kind == Token::Kind::end
            ? "the end of the line"
            : "'" + std::string(line_.text.substr(token.begin, token.size)) + "'";
    diagnostics_.error(where(token), "expected " + expected + ", found " + found);
  }

  static std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  }

  Expression predicate() { return either(); }

 private:
  void tokenize(std::size_t at) {
    const std::string_view text = line_.text;
    while (true) {
      while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
      if (at >= text.size()) break;
      Token token;
      token.begin = at;
      if (is_name_start(text[at])) {
        while (at < text.size() && is_name_char(text[at])) ++at;
        token.kind = Token::Kind::name;
      } else if (std::isdigit(static_cast<unsigned char>(text[at]))) {
        auto [end, error] =
            std::from_chars(text.data() + at, text.data() + text.size(), token.number);
        at = static_cast<std::size_t>(end - text.data());
        token.kind = error == std::errc() ? Token::Kind::number : Token::Kind::end;
      } else {
        static constexpr std::string_view kPairs[] = {
            "&&", "||", "==", "!=", "<=", ">=", "++", "--"};
        token.kind = Token::Kind::symbol;
        std::size_t width = 0;
        for (std::string_view pair : kPairs)
          if (text.substr(at).starts_with(pair)) width = 2;
        if (width == 0 && std::string_view("()!=<>;,-").find(text[at]) != std::string_view::npos)
          width = 1;
        if (width == 0) {
          diagnostics_.error(line_.at(at, 1),
                             "unexpected character '" + std::string(1, text[at]) + "'");
          failed_ = true;
          width = 1;
        }
        at += width;
      }
      token.size = at - token.begin;
      token.text = std::string(text.substr(token.begin, token.size));
      if (token.kind == Token::Kind::end) {
        diagnostics_.error(line_.at(token.begin, token.size), "malformed number");
        failed_ = true;
        token.kind = Token::Kind::number;
      }
      tokens_.push_back(std::move(token));
    }
    Token end;
    end.begin = text.size();
    tokens_.push_back(end);
  }

  Expression binary(std::string op, Expression left, Expression right, const Token& first) {
    Expression e;
    e.kind = Expression::Kind::binary;
    e.text = std::move(op);
    e.operands = {std::move(left), std::move(right)};
    e.location = from(first);
    return e;
  }

  // `next` joined by the operator `symbol` (or its word), to the left.
  Expression chain(Expression (Reader::*next)(), std::string_view symbol, std::string_view word) {
    const Token first = peek();
    Expression left = (this->*next)();
    while (!failed_ && (at_symbol(symbol) || at_word(word))) {
      take();
      left = binary(std::string(symbol), std::move(left), (this->*next)(), first);
    }
    return left;
  }

  Expression either() { return chain(&Reader::both, "||", "or"); }
  Expression both() { return chain(&Reader::negation, "&&", "and"); }

  Expression negation() {
    const Token first = peek();
    if (at_symbol("!") || at_word("not")) {
      take();
      Expression e;
      e.kind = Expression::Kind::negation;
      e.operands = {negation()};
      e.location = from(first);
      return e;
    }
    return comparison();
  }

  // `=` compares here: a predicate assigns nothing.
  Expression comparison() {
    const Token first = peek();
    Expression left = primary();
    while (!failed_) {
      std::string op;
      for (std::string_view symbol : {"==", "=", "!=", "<", ">", "<=", ">="})
        if (at_symbol(symbol)) op = symbol == "=" ? "==" : std::string(symbol);
      if (op.empty()) break;
      take();
      left = binary(op, std::move(left), primary(), first);
    }
    return left;
  }

  Expression primary() {
    Expression e;
    const Token& token = peek();
    e.location = where(token);
    if (at_symbol("(")) {
      take();
      e = either();
      if (!at_symbol(")")) {
        fail("')' to close the '('");
        return e;
      }
      take();
      return e;
    }
    if (at_symbol("-") && tokens_[at_ + 1].kind == Token::Kind::number) {
      take();
      const Token& number = take();
      e.kind = Expression::Kind::number;
      e.number = -number.number;
      return e;
    }
    if (token.kind == Token::Kind::number) {
      e.kind = Expression::Kind::number;
      e.number = take().number;
      return e;
    }
    if (token.kind == Token::Kind::name && !at_word("and") && !at_word("or") && !at_word("not")) {
      const std::string word = lower(token.text);
      if (word == "true" || word == "false") {
        e.kind = Expression::Kind::boolean;
        e.boolean = word == "true";
      } else {
        e.kind = Expression::Kind::name;
        e.text = token.text;
      }
      take();
      return e;
    }
    fail("a name, a number, true, false or '('");
    return e;
  }

  const Line& line_;
  Diagnostics& diagnostics_;
  std::vector<Token> tokens_;
  std::size_t at_ = 0;
  bool failed_ = false;
};

std::optional<std::vector<Statement>> statements(Reader& reader) {
  std::vector<Statement> action;
  while (!reader.failed()) {
    const Token first = reader.peek();
    if (first.kind != Token::Kind::name) {
      reader.fail("a statement such as 'position++' or 'parked = false'");
      break;
    }
    Statement statement;
    statement.target = {first.text, reader.where(first)};
    reader.take();
    if (reader.at_symbol("++") || reader.at_symbol("--")) {
      statement.kind =
          reader.at_symbol("++") ? Statement::Kind::increment : Statement::Kind::decrement;
      reader.take();
    } else if (reader.at_symbol("=")) {
      reader.take();
      statement.kind = Statement::Kind::assign;
      statement.value = reader.predicate();
    } else {
      reader.fail("'++', '--' or '=' after '" + first.text + "'");
      break;
    }
    statement.location = reader.from(first);
    action.push_back(std::move(statement));
    if (reader.at_end()) break;
    if (!reader.at_symbol(";") && !reader.at_symbol(",")) {
      reader.fail("';' between statements, or the end of the line");
      break;
    }
    reader.take();
  }
  if (reader.failed()) return std::nullopt;
  return action;
}

}  // namespace

std::optional<Expression> read_predicate(const Value& value, Diagnostics& diagnostics) {
  Reader reader(value, diagnostics);
  Expression e = reader.predicate();
  if (!reader.failed() && !reader.at_end()) reader.fail("an operator or the end of the line");
  if (reader.failed()) return std::nullopt;
  return e;
}

std::optional<std::vector<Statement>> read_action(const Value& value, Diagnostics& diagnostics) {
  Reader reader(value, diagnostics);
  return statements(reader);
}

std::optional<EventText> read_event(const Value& value, Diagnostics& diagnostics) {
  Reader reader(value, diagnostics);
  if (!reader.at_word("when")) {
    reader.fail("'when' to start the event");
    return std::nullopt;
  }
  reader.take();
  EventText event;
  if (reader.at_word("guard")) {
    reader.take();
    event.guard_below = true;
  } else {
    event.guard = reader.predicate();
  }
  if (!reader.failed() && !reader.at_word("do")) reader.fail("'do' after the event's guard");
  if (reader.failed()) return std::nullopt;
  reader.take();
  if (reader.at_word("action")) {
    reader.take();
    event.action_below = true;
    if (!reader.at_end()) reader.fail("the end of the line after 'action'");
  } else {
    event.action = statements(reader);
  }
  if (reader.failed()) return std::nullopt;
  return event;
}

}  // namespace scenfuzz::chs
