// The top of a `.acc` file: its three parts, each once and in any order (the grammar's order is
// STATIC, DYNAMIC, ACCIDENT; the printer keeps it), then the checks of checks.hpp.
#include "lang/accident/parser.hpp"

#include "lang/accident/blocks.hpp"
#include "lang/accident/checks.hpp"
#include "lang/accident/lexer.hpp"
#include "lang/accident/parts.hpp"

namespace scenfuzz::accident {

namespace {

class Parser {
 public:
  explicit Parser(const SourceFile& source) : source_(source) {}

  ParseResult run() {
    std::vector<Token> tokens = tokenize(source_, result_.diagnostics);
    bool declarations_read = !result_.diagnostics.has_errors();
    TokenCursor cursor(std::move(tokens), result_.diagnostics);
    BlockReader blocks(cursor);
    PartReader parts{cursor, blocks, file_, {}};
    while (!cursor.at(TokenKind::end_of_file) && !cursor.too_many_errors()) {
      const std::size_t errors = result_.diagnostics.error_count();
      const bool declaring = read_part(cursor, blocks, parts);
      if (declaring && result_.diagnostics.error_count() != errors) declarations_read = false;
    }
    check_parts(cursor.peek().location);
    // Without its STATIC or DYNAMIC part a file's references would all be reported unknown.
    if (!file_.static_at.known() || !file_.dynamic_at.known()) declarations_read = false;
    check_ids(file_, result_.diagnostics);
    if (declarations_read) check_references(file_, result_.diagnostics);
    if (!result_.diagnostics.has_errors()) result_.file = std::move(file_);
    return std::move(result_);
  }

 private:
  // One part or one mistake at the top of the file. True when it was a part that declares IDs
  // (STATIC, DYNAMIC), or something not read that might have been one.
  bool read_part(TokenCursor& cursor, BlockReader& blocks, PartReader& parts) {
    const Token& token = cursor.peek();
    const std::string name = upper(token.text);
    if (token.kind == TokenKind::right_bracket) {
      cursor.error(token.location, "unexpected ']': no bracket is open here");
      cursor.take();
      return false;
    }
    if (token.kind != TokenKind::word || !takes(Context::file, name)) {
      lost_part_ = true;
      if (token.kind == TokenKind::invalid)
        cursor.skip_item();
      else
        blocks.unknown_item(Context::file);
      return true;
    }
    const Token keyword = cursor.take();
    SourceLocation& first = name == "STATIC"    ? file_.static_at
                            : name == "DYNAMIC" ? file_.dynamic_at
                                                : file_.accident_at;
    if (first.known()) {
      cursor.error(keyword.location, "a second " + name + " part (the first is at " + place(first) +
                                         "): a description has one of each");
    }
    const SourceLocation kept = first;
    if (name == "STATIC") parts.read_static(keyword);
    if (name == "DYNAMIC") parts.read_dynamic(keyword);
    if (name == "ACCIDENT") parts.read_accident(keyword);
    if (kept.known()) first = kept;
    return name != "ACCIDENT";
  }

  // The parts missing, reported at the end of the file (unless something unreadable stood at
  // the top, which may have been the part meant).
  void check_parts(const SourceLocation& end) {
    if (lost_part_) return;
    if (!file_.static_at.known() && !file_.dynamic_at.known() && !file_.accident_at.known())
      return result_.diagnostics.error(
          end,
          "the file describes nothing: a description has a STATIC, a DYNAMIC and an "
          "ACCIDENT part");
    if (!file_.static_at.known())
      result_.diagnostics.error(end,
                                "the file has no STATIC part: add 'STATIC [ ROAD [ KIND = "
                                "crossroad; ] ]'");
    if (!file_.dynamic_at.known())
      result_.diagnostics.error(end,
                                "the file has no DYNAMIC part: add 'DYNAMIC [ VEHICLE [ ... "
                                "] ]'");
    if (!file_.accident_at.known())
      result_.diagnostics.error(end,
                                "the file has no ACCIDENT part: add 'ACCIDENT [ COLLISION "
                                "[ ... ] ]'");
  }

  const SourceFile& source_;
  ParseResult result_;
  File file_;
  bool lost_part_ = false;
};

}  // namespace

ParseResult parse(const SourceFile& source) { return Parser(source).run(); }

}  // namespace scenfuzz::accident
