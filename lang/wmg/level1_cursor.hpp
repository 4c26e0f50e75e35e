// The level-1 parser's reading machinery (internal to the WMG front end): a cursor over the
// tokens of the controlled English sentences, matching the grammar's multi-word phrases, with
// messages that say what was expected after which words and suggest the closest spelling, and
// speculative reading for the places where English needs a look further ahead.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/syntax_values.hpp"
#include "lang/wmg/token.hpp"
#include "lang/wmg/vocabulary.hpp"

namespace scenfuzz::wmg::detail {

// Thrown after a level-1 syntax error has been reported; caught where the parser can resume.
struct SentenceError {};

class SentenceCursor {
 public:
  SentenceCursor(const SourceFile& file, const std::vector<Token>& tokens, Diagnostics& diagnostics)
      : file_(file), tokens_(tokens), diagnostics_(&diagnostics) {}

  // ---- looking at tokens ----
  const Token& peek(std::size_t ahead = 0) const;
  bool at(TokenKind kind, std::size_t ahead = 0) const { return peek(ahead).kind == kind; }
  bool at_word(std::string_view word, std::size_t ahead = 0) const;
  // The number of tokens of `phrase` ("in front of", "T-Junction") if it starts `ahead` tokens
  // from here, else 0.
  std::size_t phrase_length(std::string_view phrase, std::size_t ahead = 0) const;
  bool at_phrase(std::string_view phrase, std::size_t ahead = 0) const {
    return phrase_length(phrase, ahead) > 0;
  }
  // The number of tokens of the longest phrase of `vocabulary` starting `ahead` tokens from here
  // (0 when none does), and which phrase it is.
  std::size_t match(const Vocabulary& vocabulary, std::size_t ahead = 0,
                    std::string* phrase = nullptr) const;
  const Token& take();
  void take(std::size_t count);
  const Token& previous() const;
  std::size_t position() const { return pos_; }
  SourceLocation span_from(const SourceLocation& first) const;

  // ---- errors ----
  // Reports (unless the token here is one the lexer already reported) and throws SentenceError.
  [[noreturn]] void fail(SourceLocation where, const std::string& message);
  // Reports and carries on: the sentence reads well but says something impossible.
  void error(SourceLocation where, const std::string& message);
  bool too_many_errors() const { return diagnostics_->too_many_errors(); }
  // Skips past the next '.' (or to the end of the file): where the next sentence starts.
  void skip_sentence();

  // Runs `read` from here; when it fails, nothing it reported is kept and the cursor is back where
  // it was. For English that only a look ahead can tell apart ("A, B and C, ..." as conditions).
  template <typename Read>
  bool attempt(Read&& read) {
    std::size_t start = pos_;
    Diagnostics* real = diagnostics_;
    Diagnostics scratch;
    diagnostics_ = &scratch;
    bool succeeded = true;
    try {
      read();
    } catch (const SentenceError&) {
      succeeded = false;
    }
    diagnostics_ = real;
    if (!succeeded || scratch.has_errors()) {
      pos_ = start;
      return false;
    }
    return true;
  }

  // ---- reading ----
  // `after` quotes the words before the expected ones, for messages: "'During the'".
  SourceLocation expect_phrase(std::string_view phrase, const std::string& after);
  const Token& expect(TokenKind kind, const std::string& after);
  // The longest phrase of the vocabulary, or a STRING where it allows one.
  Label label(const Vocabulary& vocabulary, const std::string& after);
  // An ID: a word that is not a road or lane id.
  Identifier id(const std::string& what, const std::string& after);
  // A ROAD_ID: R and digits.
  Identifier road_id(const std::string& what, const std::string& after);
  // Any name: a road, a junction or an actor.
  Identifier name(const std::string& what, const std::string& after);
  Text string(const std::string& what, const std::string& after);
  WholeNumber whole_number(const std::string& what, const std::string& after);

  // "expected X after Y, found Z", with the closest spelling among `candidates` when the words
  // here look like a misspelling of one.
  std::string expected_message(const std::string& expected, const std::string& after,
                               const std::vector<std::string>& candidates = {}) const;
  [[noreturn]] void fail_expected(const std::string& expected, const std::string& after,
                                  const std::vector<std::string>& candidates = {});

 private:
  const SourceFile& file_;
  const std::vector<Token>& tokens_;
  Diagnostics* diagnostics_;
  std::size_t pos_ = 0;
};

// "'a'", "'a' or 'b'", "'a', 'b' or 'c'".
std::string quoted_alternatives(const std::vector<std::string>& phrases);

}  // namespace scenfuzz::wmg::detail
