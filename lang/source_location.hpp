// Where a piece of the IR came from in the user's file, so that errors and emitted findings point
// back into it.
#pragma once

#include <cstdint>

namespace scenfuzz {

struct SourceLocation {
  std::uint32_t line = 0;    // 1-based; 0 means "no location"
  std::uint32_t column = 0;  // 1-based, counted in characters (UTF-8 code points)
  std::uint32_t offset = 0;  // byte offset of the first character
  std::uint32_t length = 0;  // bytes covered

  bool known() const { return line != 0; }
  std::uint32_t end_offset() const { return offset + length; }

  // IR equality is structural: where a node was written is not part of what it means, so that
  // print(parse(f)) compares equal to parse(f) although the layout differs.
  bool operator==(const SourceLocation&) const { return true; }
};

// The span from the start of `first` to the end of `last`.
inline SourceLocation span(const SourceLocation& first, const SourceLocation& last) {
  SourceLocation s = first;
  if (last.end_offset() > first.offset) s.length = last.end_offset() - first.offset;
  return s;
}

}  // namespace scenfuzz
