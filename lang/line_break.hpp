// What ends a line in a scenario file: LF (Unix), CRLF (Windows) or a lone CR (old Mac). Every
// part of the front ends that counts lines or finds a line's end asks here, so that line:column
// positions, comments and quoted source lines agree whatever the file's line endings.
#pragma once

#include <cstddef>
#include <string_view>

namespace scenfuzz {

// The bytes of the line break that starts at text[i]: 2 for CRLF, 1 for LF or a lone CR, 0 when
// none starts there.
inline std::size_t line_break_width(std::string_view text, std::size_t i) {
  if (i >= text.size()) return 0;
  if (text[i] == '\n') return 1;
  if (text[i] != '\r') return 0;
  return i + 1 < text.size() && text[i + 1] == '\n' ? 2 : 1;
}

inline bool is_line_break_byte(char c) { return c == '\n' || c == '\r'; }

// The offset of the first line break at or after `from` (text.size() when there is none).
inline std::size_t find_line_break(std::string_view text, std::size_t from) {
  std::size_t at = text.find_first_of("\r\n", from);
  return at == std::string_view::npos ? text.size() : at;
}

}  // namespace scenfuzz
