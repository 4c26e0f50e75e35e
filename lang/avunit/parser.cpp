#include "lang/avunit/parser.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "lang/avunit/token_window.hpp"

namespace scenfuzz::avunit {

namespace {

// Thrown after a syntax error has been reported; caught where the statement started.
struct SyntaxError {};

constexpr int kImplies = 1, kOr = 2, kAnd = 3, kUntil = 4, kCompare = 5, kAdd = 6, kMultiply = 7,
              kPower = 8;
// Deep enough for any real file, shallow enough that recursion can never exhaust the stack.
constexpr int kMaxNesting = 200;
// Loops build long chains (`1 + 1 + ... + 1`, `a[b][c]...`) without recursing; their height is
// bounded too, because everything after the parser walks the tree recursively.
constexpr int kMaxDepth = 256;

// A window over tokens already read; `tokens` ends with end_of_file and outlives the window.
TokenWindow window_over(const std::vector<Token>& tokens) {
  return TokenWindow([&tokens, next = std::size_t{0}]() mutable {
    return tokens[std::min(next++, tokens.size() - 1)];
  });
}

bool is_comparison(TokenKind kind) {
  switch (kind) {
    case TokenKind::less:
    case TokenKind::less_equal:
    case TokenKind::greater:
    case TokenKind::greater_equal:
    case TokenKind::equal:
    case TokenKind::not_equal: return true;
    default: return false;
  }
}

class Parser {
 public:
  Parser(TokenWindow tokens, Diagnostics& diagnostics)
      : tokens_(std::move(tokens)), diagnostics_(diagnostics) {}

  // A whole input that is one expression (a formula given on the command line).
  std::optional<Syntax> lone_expression() {
    try {
      nesting_ = 0;
      Syntax result = expression(kImplies);
      if (!at(TokenKind::end_of_file))
        fail(peek().location, "expected the end of the formula, found " + describe(peek()));
      return result;
    } catch (const SyntaxError&) {
      return std::nullopt;
    }
  }

  void run(const std::function<void(Statement)>& each) {
    while (!at(TokenKind::end_of_file) && !diagnostics_.too_many_errors()) {
      if (at(TokenKind::semicolon)) {
        ++pos_;  // an empty statement, e.g. the `;` LawBreaker files leave after a `}`
        continue;
      }
      std::size_t start = pos_;
      // Nothing before the previous token is looked at again.
      tokens_.forget_before(start > 0 ? start - 1 : 0);
      nesting_ = 0;
      partial_ = Statement{};
      try {
        each(statement());
      } catch (const SyntaxError&) {
        // The name is still bound, to an error, so that its uses stay silent.
        if (!partial_.name.empty() && partial_.kind != StatementKind::assertion) {
          partial_.value.kind = SyntaxKind::error;
          each(partial_);
        }
        recover(start);
      }
    }
  }

 private:
  const Token& peek(std::size_t ahead = 0) { return tokens_.at(pos_ + ahead); }
  bool at(TokenKind kind) { return peek().kind == kind; }
  bool at_word(const char* word, std::size_t ahead = 0) {
    return peek(ahead).kind == TokenKind::identifier && peek(ahead).text == word;
  }
  const Token& take() {
    const Token& token = peek();
    if (token.kind != TokenKind::end_of_file) ++pos_;
    return token;
  }
  const Token& previous() { return tokens_.at(pos_ > 0 ? pos_ - 1 : 0); }

  // A token the lexer could not read has been reported already: failing at it says nothing more.
  [[noreturn]] void fail(SourceLocation where, const std::string& message) {
    if (peek().kind != TokenKind::invalid) diagnostics_.error(where, message);
    throw SyntaxError{};
  }

  // `name =`, `name |=` or `Trace name =` at token i: `=` and `|=` occur nowhere else, so this is
  // certainly where a statement starts.
  bool statement_starts_at(std::size_t i) {
    auto kind = [&](std::size_t k) { return tokens_.at(k).kind; };
    if (kind(i) != TokenKind::identifier) return false;
    if (kind(i + 1) == TokenKind::assign || kind(i + 1) == TokenKind::satisfies) return true;
    return tokens_.at(i).text == "Trace" && kind(i + 1) == TokenKind::identifier &&
           kind(i + 2) == TokenKind::assign;
  }

  // Just after the previous token: where a missing `;` or `)` belongs.
  SourceLocation after_previous() {
    const Token& token = previous();
    SourceLocation where = token.location;
    std::uint32_t characters = 0;
    for (char c : token.text)
      if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++characters;
    if (token.kind == TokenKind::string) characters += 2;  // the quotes
    where.column += characters;
    where.offset += where.length;
    where.length = 1;
    return where;
  }

  // Records the height of a node whose children are complete.
  Syntax& deepen(Syntax& node) {
    int deepest = 0;
    for (const Syntax& child : node.children) deepest = std::max(deepest, child.depth);
    node.depth = deepest + 1;
    if (node.depth > kMaxDepth)
      fail(node.location, "expression too deeply nested or too long: split it into named parts");
    return node;
  }

  const Token& expect(TokenKind kind, const std::string& context) {
    if (!at(kind)) {
      bool closing = kind == TokenKind::semicolon || kind == TokenKind::right_paren ||
                     kind == TokenKind::right_brace || kind == TokenKind::right_bracket;
      SourceLocation where = closing && pos_ > 0 ? after_previous() : peek().location;
      fail(where, "expected " + describe(kind) + " " + context + ", found " + describe(peek()));
    }
    return take();
  }

  // Skips the rest of the statement that started at `start`: up to its `;` — one inside the
  // braces of CreateScenario{...} does not count, and no other bracket can hold a `;` — or up to
  // the start of the next statement, whichever comes first after the error.
  void recover(std::size_t start) {
    std::size_t error_at = pos_;
    std::vector<bool> braces;  // open braces; true for those of CreateScenario
    // The end_of_file token ends the loop.
    for (std::size_t i = start;; ++i) {
      TokenKind kind = tokens_.at(i).kind;
      bool in_scenario = std::find(braces.begin(), braces.end(), true) != braces.end();
      if (kind == TokenKind::end_of_file ||
          (i > start && i >= error_at && statement_starts_at(i))) {
        pos_ = i;
        return;
      }
      if (kind == TokenKind::left_brace)
        braces.push_back(i > 0 && tokens_.at(i - 1).kind == TokenKind::identifier &&
                         tokens_.at(i - 1).text == "CreateScenario");
      if (kind == TokenKind::right_brace && !braces.empty()) braces.pop_back();
      if (kind == TokenKind::semicolon && !in_scenario && i >= error_at) {
        pos_ = i + 1;
        return;
      }
    }
  }

  Statement statement() {
    Statement result;
    const Token& first = peek();
    result.location = first.location;
    if (first.kind != TokenKind::identifier)
      fail(first.location,
           "expected a statement ('name = value;', 'Trace name = EXE(scenario);' "
           "or 'trace |= formula;'), found " +
               describe(first));
    if (first.text == "Trace" && peek(1).kind == TokenKind::identifier) {
      take();
      result.kind = StatementKind::trace_declaration;
      result.name = peek().text;
      result.name_location = take().location;
      expect(TokenKind::assign, "after the trace name");
      partial_ = result;
    } else {
      result.name = first.text;
      result.name_location = take().location;
      if (at(TokenKind::assign)) {
        result.kind = StatementKind::assignment;
      } else if (at(TokenKind::satisfies)) {
        result.kind = StatementKind::assertion;
      } else {
        fail(peek().location,
             "expected '=' or '|=' after '" + result.name + "', found " + describe(peek()));
      }
      take();
      partial_ = result;
    }
    result.value = expression(kImplies);
    const char* context = result.kind == StatementKind::assertion ? "after the specification"
                                                                  : "after the assignment";
    expect(TokenKind::semicolon, context);
    result.location = span(result.location, previous().location);
    return result;
  }

  static int binary_level(const Token& token) {
    switch (token.kind) {
      case TokenKind::arrow: return kImplies;
      case TokenKind::bar: return kOr;
      case TokenKind::ampersand: return kAnd;
      case TokenKind::plus:
      case TokenKind::minus:
      case TokenKind::dot_plus:
      case TokenKind::dot_minus: return kAdd;
      case TokenKind::star:
      case TokenKind::slash:
      case TokenKind::dot_star:
      case TokenKind::dot_slash: return kMultiply;
      case TokenKind::caret: return kPower;
      case TokenKind::identifier: return token.text == "U" ? kUntil : 0;
      default: return is_comparison(token.kind) ? kCompare : 0;
    }
  }

  // Counts recursion depth; unwinds with the exceptions that end a statement.
  struct Nesting {
    explicit Nesting(Parser& parser) : owner(parser) {
      if (++owner.nesting_ > kMaxNesting)
        owner.fail(owner.peek().location, "expression nested too deeply");
    }
    ~Nesting() { --owner.nesting_; }
    Parser& owner;
  };

  Syntax expression(int min_level) {
    Nesting nesting(*this);
    Syntax left = prefix();
    bool left_is_comparison = false;
    while (true) {
      const Token& op = peek();
      int level = binary_level(op);
      if (level == 0 || level < min_level) break;
      if (level == kCompare && left_is_comparison)
        fail(op.location, "comparisons cannot be chained: write 'a < b & b < c'");
      take();
      Syntax node;
      node.op = op.kind;
      node.kind = SyntaxKind::binary;
      if (level == kUntil) {
        node.kind = SyntaxKind::until;
        node.interval = optional_interval();
      }
      Syntax right = expression(level + 1);
      node.location = span(left.location, right.location);
      node.children.push_back(std::move(left));
      node.children.push_back(std::move(right));
      left = std::move(deepen(node));
      left_is_comparison = level == kCompare;
    }
    return left;
  }

  Syntax prefix() {
    Nesting nesting(*this);
    const Token& token = peek();
    if (token.kind == TokenKind::minus || token.kind == TokenKind::plus ||
        token.kind == TokenKind::tilde) {
      take();
      Syntax node;
      node.kind = SyntaxKind::unary;
      node.op = token.kind;
      // `~` negates a whole comparison; a sign belongs to the number right after it.
      node.children.push_back(token.kind == TokenKind::tilde ? expression(kCompare) : prefix());
      node.location = span(token.location, node.children[0].location);
      return deepen(node);
    }
    if (token.kind == TokenKind::identifier &&
        (token.text == "G" || token.text == "F" || token.text == "X")) {
      take();
      Syntax node;
      node.kind = SyntaxKind::temporal;
      node.text = token.text;
      node.interval = optional_interval();
      node.children.push_back(expression(kCompare));
      node.location = span(token.location, node.children[0].location);
      return deepen(node);
    }
    return postfix();
  }

  // `[a:b]` or `[a,b]` after G, F, X or U. `[0:10]` arrives as one time token (H:MM).
  std::optional<IntervalSyntax> optional_interval() {
    if (!at(TokenKind::left_bracket)) return std::nullopt;
    IntervalSyntax interval;
    interval.location = take().location;
    // Whatever its digits, a time token here is two bounds: `[0:60]` is 0 to 60 seconds, and
    // `[-1:10]` is -1 to 10.
    auto two_bounds = [&](std::size_t ahead) {
      const Token& token = peek(ahead);
      return token.kind == TokenKind::time && token.text.find(':') == token.text.rfind(':') &&
             peek(ahead + 1).kind == TokenKind::right_bracket;
    };
    const bool signed_time = (at(TokenKind::minus) || at(TokenKind::plus)) && two_bounds(1);
    if (two_bounds(0) || signed_time) {
      const double sign = signed_time && take().kind == TokenKind::minus ? -1.0 : 1.0;
      const Token& time = take();
      std::size_t colon = time.text.find(':');
      interval.lower = sign * std::stod(time.text.substr(0, colon));
      interval.upper = std::stod(time.text.substr(colon + 1));
    } else {
      interval.lower = interval_bound();
      if (!at(TokenKind::colon) && !at(TokenKind::comma))
        fail(peek().location,
             "expected ':' or ',' between the bounds of the interval, found " + describe(peek()));
      take();
      interval.upper = interval_bound();
    }
    expect(TokenKind::right_bracket, "to close the interval");
    interval.location = span(interval.location, previous().location);
    return interval;
  }

  double interval_bound() {
    double sign = 1.0;
    if (at(TokenKind::minus) || at(TokenKind::plus))
      sign = take().kind == TokenKind::minus ? -1 : 1;
    if (!at(TokenKind::number))
      fail(peek().location,
           "expected a number of seconds as interval bound, found " + describe(peek()));
    return sign * take().number;
  }

  Syntax postfix() {
    Syntax node = primary();
    while (true) {
      const Token& token = peek();
      if (token.kind == TokenKind::left_paren && node.kind == SyntaxKind::identifier) {
        Syntax call;
        call.kind = SyntaxKind::call;
        call.text = node.text;
        take();
        call.children =
            elements(TokenKind::right_paren, "to close the argument list of '" + node.text + "'");
        call.location = span(node.location, previous().location);
        node = std::move(deepen(call));
      } else if (token.kind == TokenKind::left_bracket) {
        take();
        Syntax index;
        index.kind = SyntaxKind::index;
        index.children.push_back(std::move(node));
        index.children.push_back(expression(kImplies));
        expect(TokenKind::right_bracket, "to close the index");
        index.location = span(index.children[0].location, previous().location);
        node = std::move(deepen(index));
      } else if (token.kind == TokenKind::dot) {
        take();
        if (!at(TokenKind::identifier))
          fail(peek().location, "expected a name after '.', found " + describe(peek()));
        Syntax member;
        member.kind = SyntaxKind::member;
        member.text = take().text;
        member.location = span(node.location, previous().location);
        member.children.push_back(std::move(node));
        node = std::move(deepen(member));
      } else if (at_word("pi")) {
        take();
        node = wrap(SyntaxKind::pi, std::move(node), "pi");
      } else if (at_word("deg") || at_word("rad")) {
        node = wrap(SyntaxKind::angle, std::move(node), take().text);
        if (at_word("related")) {
          take();
          if (!at_word("to"))
            fail(peek().location, "expected 'to' after 'related', found " + describe(peek()));
          take();
          node.children.push_back(direction());
          node.location = span(node.location, node.children.back().location);
          deepen(node);
        }
      } else if (at_word("range") && peek(1).kind == TokenKind::left_paren &&
                 (node.kind == SyntaxKind::tuple || node.kind == SyntaxKind::call ||
                  node.kind == SyntaxKind::identifier)) {
        node = coordinate_range(std::move(node));
      } else {
        return node;
      }
    }
  }

  Syntax wrap(SyntaxKind kind, Syntax inner, std::string text) {
    Syntax node;
    node.kind = kind;
    node.text = std::move(text);
    node.location = span(inner.location, previous().location);
    node.children.push_back(std::move(inner));
    return deepen(node);
  }

  // After `related to`: a lane position "lane"->s, an actor, or EGO.
  Syntax direction() {
    Syntax target = postfix();
    if (!at(TokenKind::arrow)) return target;
    Syntax node;
    node.kind = SyntaxKind::binary;
    node.op = take().kind;
    Syntax offset = expression(kAdd);
    node.location = span(target.location, offset.location);
    node.children.push_back(std::move(target));
    node.children.push_back(std::move(offset));
    return deepen(node);
  }

  // `(x, y) range(a, b) & (c, d)`: x varies by an offset in [a, b], y by one in [c, d].
  Syntax coordinate_range(Syntax base) {
    SourceLocation keyword = take().location;
    Syntax node;
    node.kind = SyntaxKind::coordinate_range;
    Syntax x_range = primary();
    // The x range's span starts at `range`, so `range(a, b) & (c, d)` is one replaceable span.
    x_range.location = span(keyword, x_range.location);
    if (!at(TokenKind::ampersand))
      fail(peek().location,
           "expected '&' and the y range after the x range of a coordinate, found " +
               describe(peek()));
    take();
    if (!at(TokenKind::left_paren))
      fail(peek().location,
           "expected the y range '(lower, upper)' after '&', found " + describe(peek()));
    Syntax y_range = primary();
    node.location = span(base.location, y_range.location);
    node.children.push_back(std::move(base));
    node.children.push_back(std::move(x_range));
    node.children.push_back(std::move(y_range));
    return deepen(node);
  }

  // Comma-separated elements up to `close`; an element may be left out (`a, , b`).
  std::vector<Syntax> elements(TokenKind close, const std::string& context) {
    std::vector<Syntax> result;
    if (at(close)) {
      take();
      return result;
    }
    while (true) {
      if (at(TokenKind::comma) || at(close)) {
        Syntax empty;
        empty.kind = SyntaxKind::empty;
        empty.location = peek().location;
        result.push_back(empty);
      } else {
        result.push_back(element());
      }
      if (at(TokenKind::comma)) {
        take();
        continue;
      }
      expect(close, context);
      return result;
    }
  }

  // An element of a list; inside a set it may be keyed (`rain: 0.5`, `'rain': 0.5`).
  Syntax element() {
    bool key_ahead =
        (at(TokenKind::identifier) || at(TokenKind::string)) && peek(1).kind == TokenKind::colon;
    bool quoted_key = at(TokenKind::string) && !peek().text.empty() && peek().text.back() == ':';
    if (key_ahead || quoted_key) {
      Syntax node;
      node.kind = SyntaxKind::keyed;
      node.text = peek().text;
      if (quoted_key) node.text.pop_back();
      SourceLocation start = take().location;
      if (key_ahead) take();
      node.children.push_back(expression(kImplies));
      node.location = span(start, node.children[0].location);
      return deepen(node);
    }
    if (at(TokenKind::star)) {
      Syntax star;
      star.kind = SyntaxKind::star;
      star.location = take().location;
      return star;
    }
    return expression(kImplies);
  }

  Syntax primary() {
    const Token& token = peek();
    Syntax node;
    node.location = token.location;
    switch (token.kind) {
      case TokenKind::number:
        node.kind = SyntaxKind::number;
        node.number = token.number;
        node.text = token.text;
        take();
        return node;
      case TokenKind::string:
        node.kind = SyntaxKind::string;
        node.text = token.text;
        take();
        return node;
      case TokenKind::time:
        if (token.invalid_time)
          fail(token.location,
               "invalid time of day '" + token.text + "': expected hours 0-24 and minutes 00-59");
        node.kind = SyntaxKind::time;
        node.number = token.number;
        node.text = token.text;
        take();
        return node;
      case TokenKind::identifier:
        // Where an operand is expected, `U(` is scenest's uniform motion `U(state)`; after an
        // operand `U` is until (see binary_level). A bare `U` here can be neither.
        if (token.text == "U" && peek(1).kind != TokenKind::left_paren)
          fail(token.location,
               "'U' is the until operator ('a U b'); uniform motion is written "
               "'uniform(state)' or 'U(state)'");
        if (token.text == "CreateScenario" && peek(1).kind == TokenKind::left_brace)
          return scenario();
        if (is_frame_word(token.text) && frame_operand_at(1)) return framed();
        node.kind = SyntaxKind::identifier;
        node.text = token.text;
        take();
        return node;
      case TokenKind::left_paren: {
        take();
        node.kind = SyntaxKind::tuple;
        bool single = !at(TokenKind::right_paren);
        node.children = elements(TokenKind::right_paren, "to close the parenthesis");
        // `(x)` groups; `(x,)` and `(x, y)` are tuples.
        node.parenthesised = single && node.children.size() == 1 &&
                             previous().kind == TokenKind::right_paren &&
                             tokens_.at(pos_ - 2).kind != TokenKind::comma;
        node.location = span(token.location, previous().location);
        return deepen(node);
      }
      case TokenKind::left_brace:
        take();
        node.kind = SyntaxKind::set;
        node.children = elements(TokenKind::right_brace, "to close the set");
        node.location = span(token.location, previous().location);
        return deepen(node);
      default: fail(token.location, "expected a value, found " + describe(token));
    }
  }

  static bool is_frame_word(const std::string& word) {
    return word == "IMU" || word == "ENU" || word == "WGS84";
  }

  // `IMU yyyy`, `IMU "lane"->5`: a frame before a name, a string or a number. `IMU (x, y)` stays
  // a call, as it always parsed.
  bool frame_operand_at(std::size_t ahead) {
    TokenKind kind = peek(ahead).kind;
    return kind == TokenKind::identifier || kind == TokenKind::string || kind == TokenKind::number;
  }

  // A frame word and its operand, as the call `IMU(operand)` the elaborator already reads. The
  // operand may be a lane position `a -> s`: scenest's <position> puts the frame before its
  // <coordinate>, which includes `<lane ID> -> <real value>`.
  Syntax framed() {
    Syntax node;
    node.kind = SyntaxKind::call;
    node.text = peek().text;
    node.location = take().location;
    Syntax operand = postfix();
    if (at(TokenKind::arrow)) {
      Syntax lane;
      lane.kind = SyntaxKind::binary;
      lane.op = take().kind;
      Syntax offset = expression(kAdd);
      lane.location = span(operand.location, offset.location);
      lane.children.push_back(std::move(operand));
      lane.children.push_back(std::move(offset));
      operand = std::move(deepen(lane));
    }
    node.location = span(node.location, operand.location);
    node.children.push_back(std::move(operand));
    return deepen(node);
  }

  // CreateScenario{load(map); ego; npcs; pedestrians; obstacles; [environment;] [traffic;]}
  Syntax scenario() {
    Syntax node;
    node.kind = SyntaxKind::scenario;
    node.location = take().location;
    take();  // {
    while (!at(TokenKind::right_brace)) {
      if (at(TokenKind::end_of_file))
        fail(after_previous(), "expected '}' to close CreateScenario{...}, found end of file");
      if (statement_starts_at(pos_))
        fail(after_previous(),
             "expected '}' to close CreateScenario{...} before the next statement");
      node.children.push_back(expression(kImplies));
      // The `;` after the last slot may be left out.
      if (at(TokenKind::semicolon)) {
        take();
      } else if (!at(TokenKind::right_brace)) {
        fail(after_previous(),
             "expected ';' after this slot of CreateScenario{...}, found " + describe(peek()));
      }
    }
    take();  // }
    node.location = span(node.location, previous().location);
    return deepen(node);
  }

  TokenWindow tokens_;
  Diagnostics& diagnostics_;
  std::size_t pos_ = 0;
  int nesting_ = 0;
  Statement partial_;  // the statement being parsed, as far as its name
};

}  // namespace

void parse_statements(TokenReader& reader, Diagnostics& diagnostics,
                      const std::function<void(Statement)>& each) {
  Parser(TokenWindow([&reader] { return reader.next(); }), diagnostics).run(each);
}

std::optional<Syntax> parse_lone_expression(const std::vector<Token>& tokens,
                                            Diagnostics& diagnostics) {
  return Parser(window_over(tokens), diagnostics).lone_expression();
}

}  // namespace scenfuzz::avunit
