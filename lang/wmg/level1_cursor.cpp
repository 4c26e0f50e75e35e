#include "lang/wmg/level1_cursor.hpp"

#include <algorithm>
#include <charconv>
#include <optional>

#include "lang/wmg/parser_cursor.hpp"

namespace scenfuzz::wmg::detail {

namespace {

bool piece_matches(const Token& token, std::string_view piece) {
  return token.kind != TokenKind::string && token.kind != TokenKind::end_of_file &&
         token.kind != TokenKind::invalid && token.text == piece;
}

bool word_like(const Token& token) {
  return token.kind == TokenKind::word || token.kind == TokenKind::minus;
}

}  // namespace

std::string quoted_alternatives(const std::vector<std::string>& phrases) {
  std::string text;
  for (std::size_t i = 0; i < phrases.size(); ++i) {
    if (i > 0) text += i + 1 == phrases.size() ? " or " : ", ";
    text += "'" + phrases[i] + "'";
  }
  return text;
}

const Token& SentenceCursor::peek(std::size_t ahead) const {
  std::size_t i = pos_ + ahead;
  return i < tokens_.size() ? tokens_[i] : tokens_.back();
}

bool SentenceCursor::at_word(std::string_view word, std::size_t ahead) const {
  return at(TokenKind::word, ahead) && peek(ahead).text == word;
}

std::size_t SentenceCursor::phrase_length(std::string_view phrase, std::size_t ahead) const {
  std::vector<std::string> pieces = phrase_pieces(phrase);
  for (std::size_t i = 0; i < pieces.size(); ++i)
    if (!piece_matches(peek(ahead + i), pieces[i])) return 0;
  return pieces.size();
}

std::size_t SentenceCursor::match(const Vocabulary& vocabulary, std::size_t ahead,
                                  std::string* phrase) const {
  std::size_t best = 0;
  for (const std::string& candidate : vocabulary.phrases) {
    std::size_t length = phrase_length(candidate, ahead);
    if (length > best) {
      best = length;
      if (phrase) *phrase = candidate;
    }
  }
  return best;
}

const Token& SentenceCursor::take() {
  const Token& token = peek();
  if (pos_ + 1 < tokens_.size()) ++pos_;
  return token;
}

void SentenceCursor::take(std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) take();
}

const Token& SentenceCursor::previous() const { return tokens_[pos_ > 0 ? pos_ - 1 : 0]; }

SourceLocation SentenceCursor::span_from(const SourceLocation& first) const {
  return span(first, previous().location);
}

void SentenceCursor::fail(SourceLocation where, const std::string& message) {
  if (peek().kind != TokenKind::invalid) diagnostics_->error(where, message);
  throw SentenceError{};
}

void SentenceCursor::error(SourceLocation where, const std::string& message) {
  diagnostics_->error(where, message);
}

void SentenceCursor::skip_sentence() {
  while (!at(TokenKind::end_of_file) && !at(TokenKind::dot)) take();
  if (at(TokenKind::dot)) take();
}

std::string SentenceCursor::expected_message(const std::string& expected, const std::string& after,
                                             const std::vector<std::string>& candidates) const {
  std::string message = "expected " + expected;
  if (!after.empty()) message += " after " + after;
  message += ", found " + describe(peek());
  // Compare the candidates of each length in words with as many words written here, longest
  // first, so that "heavy rian" finds "heavy rain" and "dya" finds "day".
  std::size_t longest = 0;
  for (const std::string& candidate : candidates)
    longest = std::max(longest, phrase_pieces(candidate).size());
  for (std::size_t length = longest; length > 0; --length) {
    bool written_here = true;
    for (std::size_t i = 0; i < length; ++i)
      written_here =
          written_here && word_like(peek(i)) && peek(i).location.line == peek().location.line;
    if (!written_here) continue;
    std::vector<std::string> same_length;
    for (const std::string& candidate : candidates)
      if (phrase_pieces(candidate).size() == length) same_length.push_back(candidate);
    SourceLocation written = span(peek().location, peek(length - 1).location);
    std::string_view text = file_.text();
    std::string words = written.offset < text.size()
                            ? std::string(text.substr(written.offset, written.length))
                            : std::string();
    if (std::optional<std::string> suggestion = closest_spelling(same_length, words)) {
      message += "; did you mean '" + *suggestion + "'?";
      break;
    }
  }
  return message;
}

void SentenceCursor::fail_expected(const std::string& expected, const std::string& after,
                                   const std::vector<std::string>& candidates) {
  fail(peek().location, expected_message(expected, after, candidates));
}

SourceLocation SentenceCursor::expect_phrase(std::string_view phrase, const std::string& after) {
  std::size_t length = phrase_length(phrase);
  if (length == 0) {
    // Point at the first word that differs, and quote the phrase from there.
    std::vector<std::string> pieces = phrase_pieces(phrase);
    std::size_t same = 0;
    while (same < pieces.size() && piece_matches(peek(), pieces[same])) {
      take();
      ++same;
    }
    std::string rest;
    for (std::size_t i = same; i < pieces.size(); ++i) {
      bool joined = i > same && (pieces[i] == "-" || pieces[i - 1] == "-");
      rest += (i > same && !joined ? " " : "") + pieces[i];
    }
    std::string before = after;
    if (same > 0)
      before =
          "'" +
          std::string(file_.text().substr(previous().location.offset, previous().location.length)) +
          "'";
    fail_expected("'" + rest + "'", before, {rest});
  }
  SourceLocation first = peek().location;
  take(length);
  return span_from(first);
}

const Token& SentenceCursor::expect(TokenKind kind, const std::string& after) {
  if (!at(kind)) fail_expected(describe(kind), after);
  return take();
}

Label SentenceCursor::label(const Vocabulary& vocabulary, const std::string& after) {
  if (at(TokenKind::string) && vocabulary.allows_string) {
    const Token& token = take();
    return Label{token.text, true, token.location};
  }
  std::string phrase;
  std::size_t length = match(vocabulary, 0, &phrase);
  if (length == 0) {
    std::string expected =
        vocabulary.phrases.size() <= 3
            ? quoted_alternatives(vocabulary.phrases)
            : "the " + vocabulary.what + " (" + quoted_alternatives(vocabulary.phrases) + ")";
    if (vocabulary.allows_string) expected += " or a 'quoted' name";
    fail_expected(expected, after, vocabulary.phrases);
  }
  SourceLocation first = peek().location;
  take(length);
  return Label{phrase, false, span_from(first)};
}

Identifier SentenceCursor::name(const std::string& what, const std::string& after) {
  if (!at(TokenKind::word)) fail_expected(what, after);
  const Token& token = take();
  return Identifier{token.text, token.location};
}

Identifier SentenceCursor::id(const std::string& what, const std::string& after) {
  if (at(TokenKind::word) && (is_road_id(peek().text) || is_lane_id(peek().text)))
    fail(peek().location, "'" + peek().text + "' has the form of a " +
                              (is_road_id(peek().text) ? "road" : "lane") + " id; " + what +
                              " needs a name that is not R<n>, L<n> or P<n>");
  return name(what, after);
}

Identifier SentenceCursor::road_id(const std::string& what, const std::string& after) {
  if (!at(TokenKind::word) || !is_road_id(peek().text))
    fail_expected(what + " (a road id such as R1)", after);
  const Token& token = take();
  return Identifier{token.text, token.location};
}

Text SentenceCursor::string(const std::string& what, const std::string& after) {
  if (!at(TokenKind::string)) fail_expected(what + " in single quotes", after);
  const Token& token = take();
  return Text{token.text, token.location};
}

WholeNumber SentenceCursor::whole_number(const std::string& what, const std::string& after) {
  if (!at(TokenKind::number) || peek().text.find('.') != std::string::npos)
    fail_expected(what + " (a whole number)", after);
  constexpr double kLargest = 1e15;
  if (peek().number > kLargest) fail(peek().location, "number '" + peek().text + "' is too large");
  const Token& token = take();
  return WholeNumber{static_cast<std::int64_t>(token.number), token.location};
}

}  // namespace scenfuzz::wmg::detail
