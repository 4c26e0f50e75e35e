// A CH-Scenario file as lines: `#` comments cut, blanks trimmed, empty lines dropped, and each
// line's place in the file kept so that a piece of it can be located to its column.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz::chs {

struct Line {
  std::string_view text;  // from its first to its last non-blank character
  SourceLocation start;   // of text's first character

  // Where text[begin, begin + count) is (columns count UTF-8 characters).
  SourceLocation at(std::size_t begin, std::size_t count) const;
  SourceLocation whole() const { return at(0, text.size()); }
};

std::vector<Line> split_lines(const SourceFile& source);

// Lower case without blanks, underscores and hyphens: "Air_pressure", "air pressure" and
// "airPressure" are one key.
std::string normalised(std::string_view text);

std::string_view trimmed(std::string_view text);

}  // namespace scenfuzz::chs
