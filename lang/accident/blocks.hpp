// A bracket `KEYWORD [ ... ]` of the formalism, read the same way wherever it stands: the
// keywords its context takes are handed to the caller one by one, a property given twice is
// reported, a keyword of an enclosing bracket ends it (its `]` is reported missing), and an
// unknown or misplaced keyword is reported with the nearest spelling and skipped.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "lang/accident/token_cursor.hpp"
#include "lang/accident/vocabulary.hpp"

namespace scenfuzz::accident {

struct Block {
  Token keyword;
  bool closed = false;                                      // its `]` was found
  bool clean = true;                                        // nothing inside was reported
  std::map<std::string, SourceLocation, std::less<>> seen;  // keywords given (the first place)
  SourceLocation location;                                  // from the keyword to the `]`

  bool has(std::string_view name) const { return seen.count(name) > 0; }
};

// Called after an item's keyword was taken: `name` is its upper-case spelling; `again` tells
// that a property was given twice (reported already: read it, but keep the first value).
using ItemReader = std::function<void(const Token& keyword, const std::string& name, bool again)>;

class BlockReader {
 public:
  explicit BlockReader(TokenCursor& cursor) : cursor_(cursor) {}

  // Reads `[ items ]` after `keyword` (already taken), which opens a bracket of `context`.
  Block read(const Token& keyword, Context context, const ItemReader& item);
  // Reports an item that `context` does not take at the cursor, and skips it.
  void unknown_item(Context context);
  // "this VEHICLE has no KIND" at the block's keyword, when the block was read without a mistake
  // (a mistake inside may have lost the property).
  void require(const Block& block, std::string_view keyword, const std::string& message);

  // The contexts open around the cursor, outermost first.
  std::vector<Context>& open() { return open_; }

 private:
  bool encloses(std::string_view keyword) const;
  bool read_item(Block& block, Context context, const ItemReader& item);

  TokenCursor& cursor_;
  std::vector<Context> open_{Context::file};
};

std::string place(const SourceLocation& where);  // "12:5"

}  // namespace scenfuzz::accident
