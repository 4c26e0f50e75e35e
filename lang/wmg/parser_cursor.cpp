#include "lang/wmg/parser_cursor.hpp"

#include <algorithm>
#include <cmath>

namespace scenfuzz::wmg::detail {

namespace {

bool is_letter_then_digits(std::string_view text, std::string_view letters) {
  if (text.size() < 2 || letters.find(text[0]) == std::string_view::npos) return false;
  return std::all_of(text.begin() + 1, text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A phrase piece matches a word or punctuation token with the same text, never a string.
bool matches(const Token& token, const std::string& piece) {
  return token.kind != TokenKind::string && token.kind != TokenKind::invalid &&
         token.kind != TokenKind::end_of_file && token.text == piece;
}

bool is_not_a_number_word(const std::string& text) {
  std::string lower = text;
  for (char& c : lower) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

std::string list_phrases(const Vocabulary& vocabulary) {
  constexpr std::size_t kListed = 12;
  std::string list;
  for (std::size_t i = 0; i < vocabulary.phrases.size() && i < kListed; ++i)
    list += (i > 0 ? ", " : "") + vocabulary.phrases[i];
  if (vocabulary.phrases.size() > kListed)
    list += ", ... (" + std::to_string(vocabulary.phrases.size()) + " in all)";
  if (vocabulary.allows_string) list += ", or a 'quoted name'";
  return list;
}

std::string describe_each(std::initializer_list<TokenKind> kinds) {
  std::string text;
  std::size_t i = 0;
  for (TokenKind kind : kinds) {
    text += (i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + describe(kind);
    ++i;
  }
  return text;
}

}  // namespace

bool is_road_id(std::string_view text) { return is_letter_then_digits(text, "R"); }
bool is_lane_id(std::string_view text) { return is_letter_then_digits(text, "LP"); }

// ---- looking at tokens ----------------------------------------------------------------------

const Token& Cursor::peek(std::size_t ahead) const {
  std::size_t i = pos_ + ahead;
  return i < tokens_.size() ? tokens_[i] : tokens_.back();
}

bool Cursor::at_word(std::string_view word, std::size_t ahead) const {
  return peek(ahead).kind == TokenKind::word && peek(ahead).text == word;
}

bool Cursor::at_phrase(std::string_view phrase, std::size_t ahead) const {
  std::vector<std::string> pieces = phrase_pieces(phrase);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!matches(peek(ahead + i), pieces[i])) return false;
  return true;
}

bool Cursor::at_road_id(std::size_t ahead) const {
  return peek(ahead).kind == TokenKind::word && is_road_id(peek(ahead).text);
}

bool Cursor::at_section_start() const {
  return at_phrase("SCENERY ELEMENTS") || at_phrase("DYNAMIC ELEMENTS") ||
         at_phrase("INTERNAL ELEMENTS") || at_phrase("ENVIRONMENT ELEMENTS") ||
         at_phrase("TRAFFIC ELEMENTS");
}

const Token& Cursor::take() {
  const Token& token = peek();
  if (pos_ + 1 < tokens_.size()) ++pos_;
  return token;
}

const Token& Cursor::previous() const { return tokens_[pos_ > 0 ? pos_ - 1 : 0]; }

SourceLocation Cursor::span_from(const SourceLocation& first) const {
  return span(first, previous().location);
}

std::string_view Cursor::text_of(const SourceLocation& where) const {
  std::string_view text = file_.text();
  if (where.offset >= text.size()) return {};
  return text.substr(where.offset, where.length);
}

// ---- errors ----------------------------------------------------------------------------------

void Cursor::fail(SourceLocation where, const std::string& message) {
  if (peek().kind != TokenKind::invalid) diagnostics_.error(where, message);
  throw SyntaxError{};
}

void Cursor::error(SourceLocation where, const std::string& message) {
  diagnostics_.error(where, message);
}

void Cursor::resync(std::size_t item_start, const std::function<bool()>& resume) {
  if (too_many_errors()) throw SyntaxError{};
  if (pos_ <= item_start) {
    pos_ = item_start;
    take();
  }
  while (!at(TokenKind::end_of_file) && !at_section_start() && !resume()) take();
  if (at(TokenKind::end_of_file) || at_section_start()) throw SyntaxError{};
}

void Cursor::skip_to_section() {
  while (!at(TokenKind::end_of_file) && !at_section_start()) take();
}

// ---- keywords and punctuation ----------------------------------------------------------------

const Token& Cursor::expect(TokenKind kind, const std::string& context) {
  if (!at(kind))
    fail(peek().location,
         "expected " + describe(kind) + " " + context + ", found " + describe(peek()));
  return take();
}

const Token& Cursor::close(TokenKind kind, const std::string& context) {
  if (!at(kind)) {
    // Just after the previous token: where the missing bracket belongs.
    SourceLocation where = previous().location;
    for (char c : text_of(where))
      if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++where.column;
    where.offset += where.length;
    where.length = 1;
    fail(where, "expected " + describe(kind) + " " + context + ", found " + describe(peek()));
  }
  return take();
}

SourceLocation Cursor::expect_phrase(std::string_view phrase, const std::string& context) {
  std::vector<std::string> pieces = phrase_pieces(phrase);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!matches(peek(i), pieces[i]))
      fail(peek(i).location,
           "expected '" + std::string(phrase) + "' " + context + ", found " + describe(peek(i)));
  SourceLocation first = peek().location;
  for (std::size_t i = 0; i < pieces.size(); ++i) take();
  return span_from(first);
}

// ---- leaves ----------------------------------------------------------------------------------

double Cursor::signed_number(const std::string& what, SourceLocation& where) {
  SourceLocation first = peek().location;
  bool negative = at(TokenKind::minus);
  if (negative) take();
  if (!at(TokenKind::number)) {
    if (at(TokenKind::word) && is_not_a_number_word(peek().text))
      fail(peek().location, "'" + peek().text + "' is not a finite number: " + what +
                                " must be a number such as 20.5");
    fail(peek().location,
         (negative ? "expected a number after '-' for " : "expected a number for ") + what +
             ", found " + describe(peek()));
  }
  double value = take().number;
  where = span_from(first);
  return negative ? -value : value;
}

NumberRange Cursor::range(TokenKind follow, const std::string& what) {
  return range({follow}, what);
}

NumberRange Cursor::range(std::initializer_list<TokenKind> follow, const std::string& what) {
  NumberRange result;
  SourceLocation low_location;
  result.low = result.high = signed_number(what, low_location);
  result.location = low_location;
  if (at_word("to")) {
    take();
    SourceLocation high_location;
    result.high = signed_number("the upper bound of " + what, high_location);
    result.is_range = true;
    result.location = span(low_location, high_location);
    if (result.low > result.high)
      error(result.location, "inverted range: the lower bound " +
                                 std::string(text_of(low_location)) + " is above the upper bound " +
                                 std::string(text_of(high_location)));
    return result;
  }
  bool follows = std::any_of(follow.begin(), follow.end(), [&](TokenKind k) { return at(k); });
  if (!follows)
    fail(peek().location, "expected 'to' or " + describe_each(follow) +
                              " after the range's lower bound " +
                              std::string(text_of(low_location)) + ", found " + describe(peek()));
  return result;
}

NumberRange Cursor::number(const std::string& what) {
  NumberRange result;
  result.low = result.high = signed_number(what, result.location);
  if (at_word("to"))
    fail(peek().location, what + " is a single number, not a range: remove 'to' and what follows");
  return result;
}

WholeNumber Cursor::whole_number(const std::string& what) {
  WholeNumber result;
  SourceLocation first = peek().location;
  bool negative = at(TokenKind::minus);
  if (negative) take();
  if (!at(TokenKind::number) || peek().text.find('.') != std::string::npos)
    fail(peek().location, "expected a whole number for " + what + ", found " + describe(peek()));
  if (peek().number > 1e15) fail(peek().location, "number '" + peek().text + "' is too large");
  auto value = static_cast<std::int64_t>(take().number);
  result.value = negative ? -value : value;
  result.location = span_from(first);
  return result;
}

Identifier Cursor::id(const std::string& what) {
  if (at(TokenKind::string))
    fail(peek().location,
         "expected an ID for " + what + ", found " + describe(peek()) + ": IDs take no quotes");
  if (!at(TokenKind::word))
    fail(peek().location, "expected an ID for " + what + ", found " + describe(peek()));
  if (is_road_id(peek().text) || is_lane_id(peek().text))
    fail(peek().location, "'" + peek().text + "' has the form of a " +
                              (is_road_id(peek().text) ? "road" : "lane") + " id; " + what +
                              " needs an ID that is not R<n>, L<n> or P<n>");
  const Token& token = take();
  return Identifier{token.text, token.location};
}

Identifier Cursor::road_id(const std::string& what) {
  if (!at_road_id())
    fail(peek().location,
         "expected a road id such as R1 for " + what + ", found " + describe(peek()));
  const Token& token = take();
  return Identifier{token.text, token.location};
}

Identifier Cursor::lane_id(const std::string& what) {
  if (!at(TokenKind::word) || !is_lane_id(peek().text))
    fail(peek().location,
         "expected a lane id such as L1 or P1 for " + what + ", found " + describe(peek()));
  const Token& token = take();
  return Identifier{token.text, token.location};
}

LaneName Cursor::lane_name(const std::string& what) {
  LaneName result;
  result.road = road_id(what);
  if (!at(TokenKind::dot))
    fail(peek().location, "expected '.' and a lane id after '" + result.road.name +
                              "' (a lane is written " + result.road.name + ".L1), found " +
                              describe(peek()));
  take();
  result.lane = lane_id(what);
  result.location = span_from(result.road.location);
  return result;
}

Text Cursor::string(const std::string& what) {
  if (!at(TokenKind::string))
    fail(peek().location, "expected a 'quoted' string for " + what + ", found " + describe(peek()));
  const Token& token = take();
  return Text{token.text, token.location};
}

std::size_t Cursor::longest_match(const Vocabulary& vocabulary, std::string& canonical) const {
  std::size_t best = 0;
  auto consider = [&](const std::string& written, const std::string& meaning) {
    std::vector<std::string> pieces = phrase_pieces(written);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (!matches(peek(i), pieces[i])) return;
    if (pieces.size() > best) {
      best = pieces.size();
      canonical = meaning;
    }
  };
  for (const std::string& phrase : vocabulary.phrases) consider(phrase, phrase);
  for (const auto& [written, meaning] : vocabulary.aliases) consider(written, meaning);
  return best;
}

void Cursor::fail_unknown(const Vocabulary& vocabulary) {
  // Quote what was written: the words (and - / digits) on this line, up to a few.
  constexpr std::size_t kMostTokens = 6;
  std::size_t count = 0;
  while (count < kMostTokens) {
    const Token& token = peek(count);
    bool word_like =
        token.kind == TokenKind::word || token.kind == TokenKind::number ||
        (count > 0 && (token.kind == TokenKind::minus || token.kind == TokenKind::slash));
    if (!word_like || token.location.line != peek().location.line) break;
    ++count;
  }
  if (count == 0)
    fail(peek().location, "expected the " + vocabulary.what + " (" + list_phrases(vocabulary) +
                              "), found " + describe(peek()));
  SourceLocation where = span(peek().location, peek(count - 1).location);
  std::string written(text_of(where));
  std::vector<std::string> candidates = vocabulary.phrases;
  for (const auto& alias : vocabulary.aliases) candidates.push_back(alias.first);
  std::optional<std::string> suggestion = closest_spelling(candidates, written);
  std::string message = "unknown " + vocabulary.what + " '" + written + "'; ";
  if (suggestion)
    message += "did you mean '" + *suggestion + "'? Expected";
  else
    message += "expected";
  fail(where, message + " one of " + list_phrases(vocabulary));
}

Label Cursor::label(const Vocabulary& vocabulary) {
  if (at(TokenKind::string)) {
    if (!vocabulary.allows_string)
      fail(peek().location, "expected the " + vocabulary.what + " (" + list_phrases(vocabulary) +
                                "), found " + describe(peek()) + ": it takes no quoted names");
    const Token& token = take();
    return Label{token.text, true, token.location};
  }
  std::string canonical;
  std::size_t length = longest_match(vocabulary, canonical);
  if (length == 0) fail_unknown(vocabulary);
  SourceLocation first = peek().location;
  for (std::size_t i = 0; i < length; ++i) take();
  return Label{canonical, false, span_from(first)};
}

std::size_t Cursor::choice(const Vocabulary& vocabulary, SourceLocation& where) {
  Label chosen = label(vocabulary);
  where = chosen.location;
  auto found = std::find(vocabulary.phrases.begin(), vocabulary.phrases.end(), chosen.text);
  return static_cast<std::size_t>(found - vocabulary.phrases.begin());
}

// ---- lists ------------------------------------------------------------------------------------

std::string counted(std::size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

void check_count(Cursor& cursor, const WholeNumber& count, std::size_t listed,
                 SourceLocation list_location, const std::string& noun) {
  if (count.value != static_cast<std::int64_t>(listed))
    cursor.error(list_location, "the count says " + std::to_string(count.value) + " " + noun +
                                    "s but the list has " + std::to_string(listed));
}

// ---- bracketed leaves ------------------------------------------------------------------------

Label Cursor::bracketed_label(const Vocabulary& vocabulary) {
  expect(TokenKind::left_bracket, "before the " + vocabulary.what);
  Label result = label(vocabulary);
  close(TokenKind::right_bracket, "after the " + vocabulary.what);
  return result;
}

NumberRange Cursor::bracketed_range(const std::string& what) {
  expect(TokenKind::left_bracket, "before " + what);
  NumberRange result = range(TokenKind::right_bracket, what);
  close(TokenKind::right_bracket, "after " + what);
  return result;
}

NumberRange Cursor::bracketed_number(const std::string& what) {
  expect(TokenKind::left_bracket, "before " + what);
  NumberRange result = number(what);
  close(TokenKind::right_bracket, "after " + what);
  return result;
}

Identifier Cursor::bracketed_id(const std::string& what) {
  expect(TokenKind::left_bracket, "before " + what);
  Identifier result = id(what);
  close(TokenKind::right_bracket, "after " + what);
  return result;
}

LaneName Cursor::bracketed_lane_name(const std::string& what) {
  expect(TokenKind::left_bracket, "before " + what);
  LaneName result = lane_name(what);
  close(TokenKind::right_bracket, "after " + what);
  return result;
}

}  // namespace scenfuzz::wmg::detail
