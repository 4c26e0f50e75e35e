// The values of `key: value` lines: numbers, flags, free text and lists of points, each located
// in its line, and each mistake a diagnostic.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lang/chs/lines.hpp"
#include "lang/chs/syntax.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::chs {

// The rest of `line` from byte `begin` (after the colon and its blanks).
struct Value {
  const Line& line;
  std::size_t begin = 0;

  std::string_view text() const { return line.text.substr(begin); }
  SourceLocation location() const { return line.at(begin, line.text.size() - begin); }
};

// `what` names the value in messages ("the cloudiness").
std::optional<Number> read_number(const Value& value, Diagnostics& diagnostics,
                                  const std::string& what);
// 0, 1, true or false (any case).
std::optional<Flag> read_flag(const Value& value, Diagnostics& diagnostics,
                              const std::string& what);
// Any text but none.
std::optional<Text> read_text(const Value& value, Diagnostics& diagnostics,
                              const std::string& what);
// `(x, y)` points, separated by blanks or commas, from byte `begin` of `line` to its end,
// appended to `points`. False after a mistake (the points before it are kept).
bool read_points(const Line& line, std::size_t begin, std::vector<Point>& points,
                 Diagnostics& diagnostics);

}  // namespace scenfuzz::chs
