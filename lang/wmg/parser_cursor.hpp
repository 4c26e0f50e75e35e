// The parser's shared machinery (internal to the WMG front end): a cursor over the tokens with
// phrase matching for the multi-word keywords, the leaf parsers (numbers and ranges, names, lane
// names, enumeration words) and error recovery. The section parsers build on it.
#pragma once

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/syntax.hpp"
#include "lang/wmg/token.hpp"
#include "lang/wmg/vocabulary.hpp"

namespace scenfuzz::wmg::detail {

// Thrown after a syntax error has been reported; caught where the parser can resume.
struct SyntaxError {};

class Cursor {
 public:
  Cursor(const SourceFile& file, const std::vector<Token>& tokens, Diagnostics& diagnostics)
      : file_(file), tokens_(tokens), diagnostics_(diagnostics) {}

  // ---- looking at tokens ----
  const Token& peek(std::size_t ahead = 0) const;
  bool at(TokenKind kind, std::size_t ahead = 0) const { return peek(ahead).kind == kind; }
  bool at_word(std::string_view word, std::size_t ahead = 0) const;
  // Whether the keyword phrase ("Junction type", "N/A") starts `ahead` tokens from here.
  bool at_phrase(std::string_view phrase, std::size_t ahead = 0) const;
  bool at_road_id(std::size_t ahead = 0) const;
  // SCENERY ELEMENTS, DYNAMIC ELEMENTS, INTERNAL ELEMENTS, ENVIRONMENT ELEMENTS, TRAFFIC ELEMENTS.
  bool at_section_start() const;
  const Token& take();
  const Token& previous() const;
  std::size_t position() const { return pos_; }
  // From the start of `first` to the end of the last token taken.
  SourceLocation span_from(const SourceLocation& first) const;
  // The source text of a span, for messages that quote what the user wrote.
  std::string_view text_of(const SourceLocation& where) const;

  // ---- errors ----
  // Reports (unless the token here is one the lexer already reported) and throws SyntaxError.
  [[noreturn]] void fail(SourceLocation where, const std::string& message);
  // Reports and carries on: the text is well-formed but its value is wrong.
  void error(SourceLocation where, const std::string& message);
  bool too_many_errors() const { return diagnostics_.too_many_errors(); }
  // After an error in an item that started at `item_start`: skips to the next token where
  // `resume` holds. Throws SyntaxError when a section start, the end of the file or the error
  // limit comes first, abandoning the section.
  void resync(std::size_t item_start, const std::function<bool()>& resume);
  // Skips to the next section start (or the end of the file), staying if already at one.
  void skip_to_section();

  // ---- keywords and punctuation ----
  const Token& expect(TokenKind kind, const std::string& context);
  // A closing bracket that is missing is reported just after the token it should follow.
  const Token& close(TokenKind kind, const std::string& context);
  SourceLocation expect_phrase(std::string_view phrase, const std::string& context);

  // ---- leaves ----
  // DOUBLE_RANGE `a to b`, or one DOUBLE; `follow` is the token that may come after a lone number.
  NumberRange range(TokenKind follow, const std::string& what);
  NumberRange range(std::initializer_list<TokenKind> follow, const std::string& what);
  // One DOUBLE, not a range.
  NumberRange number(const std::string& what);
  WholeNumber whole_number(const std::string& what);
  Identifier id(const std::string& what);
  Identifier road_id(const std::string& what);
  Identifier lane_id(const std::string& what);
  LaneName lane_name(const std::string& what);
  Text string(const std::string& what);
  // One value of an enumeration (the longest phrase that matches), or a STRING where allowed.
  Label label(const Vocabulary& vocabulary);
  // The index of the phrase in a closed enumeration.
  std::size_t choice(const Vocabulary& vocabulary, SourceLocation& where);
  template <typename Enumeration>
  Located<Enumeration> enumerated(const Vocabulary& vocabulary) {
    Located<Enumeration> result;
    result.value = static_cast<Enumeration>(choice(vocabulary, result.location));
    return result;
  }

  // ---- bracketed leaves: '[' leaf ']' ----
  Label bracketed_label(const Vocabulary& vocabulary);
  NumberRange bracketed_range(const std::string& what);
  NumberRange bracketed_number(const std::string& what);
  Identifier bracketed_id(const std::string& what);
  LaneName bracketed_lane_name(const std::string& what);
  template <typename Enumeration>
  Located<Enumeration> bracketed_enumerated(const Vocabulary& vocabulary) {
    expect(TokenKind::left_bracket, "before the " + vocabulary.what);
    Located<Enumeration> result = enumerated<Enumeration>(vocabulary);
    close(TokenKind::right_bracket, "after the " + vocabulary.what);
    return result;
  }

 private:
  // Number of tokens of the longest phrase (or alias) of `vocabulary` matching here, and which.
  std::size_t longest_match(const Vocabulary& vocabulary, std::string& canonical) const;
  [[noreturn]] void fail_unknown(const Vocabulary& vocabulary);
  double signed_number(const std::string& what, SourceLocation& where);

  const SourceFile& file_;
  const std::vector<Token>& tokens_;
  Diagnostics& diagnostics_;
  std::size_t pos_ = 0;
};

// `item (',' item)*`, up to (not taking) whatever follows the last item.
template <typename Item>
std::vector<Item> comma_list(Cursor& cursor, const std::function<Item()>& item) {
  std::vector<Item> items{item()};
  while (cursor.at(TokenKind::comma)) {
    cursor.take();
    items.push_back(item());
  }
  return items;
}

// '[' item (',' item)* ']', and where the whole list was written.
template <typename Item>
std::vector<Item> bracketed_list(Cursor& cursor, const std::string& what,
                                 const std::function<Item()>& item,
                                 SourceLocation* where = nullptr) {
  SourceLocation first = cursor.expect(TokenKind::left_bracket, "before " + what).location;
  std::vector<Item> items = comma_list(cursor, item);
  cursor.close(TokenKind::right_bracket, "after " + what);
  if (where) *where = cursor.span_from(first);
  return items;
}

// "1 angle", "2 angles".
std::string counted(std::size_t count, const std::string& noun);

// Reports (and carries on) when a stated count differs from the length of the list it counts.
void check_count(Cursor& cursor, const WholeNumber& count, std::size_t listed,
                 SourceLocation list_location, const std::string& noun);

// Whether a word has the form of a ROAD_ID (R1) or a LANE_ID (L1, P1).
bool is_road_id(std::string_view text);
bool is_lane_id(std::string_view text);

}  // namespace scenfuzz::wmg::detail
