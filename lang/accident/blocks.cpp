// Reading a bracket and its items, and the messages for items that do not belong.
#include "lang/accident/blocks.hpp"

namespace scenfuzz::accident {

std::string place(const SourceLocation& where) {
  return std::to_string(where.line) + ":" + std::to_string(where.column);
}

Block BlockReader::read(const Token& keyword, Context context, const ItemReader& item) {
  Block block;
  block.keyword = keyword;
  const std::size_t errors = cursor_.diagnostics().error_count();
  const std::string name = upper(keyword.text);
  if (cursor_.at(TokenKind::left_bracket)) {
    cursor_.take();
  } else if (cursor_.at(TokenKind::word) && takes(context, upper(cursor_.peek().text))) {
    // `TREE ID = t1; ...`: read on as if the `[` were there.
    cursor_.error(cursor_.peek().location,
                  "expected '[' after " + name + ", found " + cursor_.found());
  } else {
    cursor_.fail("'[' after " + name);
    block.clean = false;
    block.location = span(keyword.location, cursor_.last());
    return block;
  }
  open_.push_back(context);
  while (!cursor_.too_many_errors() && read_item(block, context, item)) {
  }
  open_.pop_back();
  block.location = span(keyword.location, cursor_.last());
  block.clean = cursor_.diagnostics().error_count() == errors;
  return block;
}

// False at the end of the bracket.
bool BlockReader::read_item(Block& block, Context context, const ItemReader& item) {
  const std::string opened =
      "the " + upper(block.keyword.text) + " opened at " + place(block.keyword.location);
  const Token& token = cursor_.peek();
  switch (token.kind) {
    case TokenKind::end_of_file:
      cursor_.error(token.location,
                    "expected ']' to close " + opened + ", found the end of the file");
      return false;
    case TokenKind::right_bracket:
      cursor_.take();
      block.closed = true;
      return false;
    case TokenKind::invalid: cursor_.skip_item(); return true;
    case TokenKind::word: break;
    default:
      cursor_.fail("a keyword of " + context_name(context) + " (" + keyword_list(context) +
                   ") or ']'");
      return true;
  }
  const std::string name = upper(token.text);
  if (takes(context, name)) {
    const bool again = block.has(name) && !repeatable(name);
    if (again)
      cursor_.error(token.location, name + " is given twice in this " + upper(block.keyword.text) +
                                        " (first at " + place(block.seen.find(name)->second) + ")");
    block.seen.emplace(name, token.location);
    const Token keyword = cursor_.take();
    item(keyword, name, again);
    return true;
  }
  if (encloses(name) && cursor_.at_item_start()) {
    cursor_.error(token.location,
                  "expected ']' to close " + opened + ", found '" + token.text + "'");
    return false;
  }
  unknown_item(context);
  return true;
}

void BlockReader::unknown_item(Context context) {
  const Token& token = cursor_.peek();
  const std::string name = upper(token.text);
  const std::string where = context_name(context);
  if (token.kind != TokenKind::word) {
    cursor_.fail(context == Context::file
                     ? "STATIC, DYNAMIC or ACCIDENT"
                     : "a keyword of " + where + " (" + keyword_list(context) + ") or ']'");
    return;
  }
  std::string message;
  if (is_keyword(name)) {
    message = name + " does not belong in " + where + ", which takes " + keyword_list(context);
  } else if (auto best = nearest(token.text, keywords_of(context))) {
    message =
        "unknown keyword '" + token.text + "' in " + where + "; did you mean '" + *best + "'?";
  } else {
    message = "unknown keyword '" + token.text + "' in " + where + ", which takes " +
              keyword_list(context);
  }
  cursor_.error(token.location, message);
  cursor_.skip_item();
}

void BlockReader::require(const Block& block, std::string_view keyword,
                          const std::string& message) {
  if (block.closed && block.clean && !block.has(keyword))
    cursor_.error(block.keyword.location, message);
}

bool BlockReader::encloses(std::string_view keyword) const {
  for (std::size_t i = 0; i + 1 < open_.size(); ++i)
    if (takes(open_[i], keyword)) return true;
  return false;
}

}  // namespace scenfuzz::accident
