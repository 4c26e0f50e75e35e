// Shows text from a user's file on a terminal without letting its bytes act on the terminal:
// control bytes, NULs and bytes that are not well-formed UTF-8 are written as `\xNN`, so that a
// diagnostic quoting a damaged file neither hides part of the line nor sends escape codes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace scenfuzz {

// How the character that starts at text[i] is shown.
struct ShownCharacter {
  std::string text;       // what to print for it
  std::size_t bytes = 1;  // the bytes of the input it stands for
  std::size_t width = 1;  // terminal columns it takes (a tab counts one and is printed as a tab)
  bool escaped = false;   // written as `\xNN`
};

// A tab stays a tab, printable ASCII and well-formed UTF-8 stay as they are (one column each), and
// every other byte (NUL, control bytes, DEL, C1 controls, malformed UTF-8) becomes `\xNN`.
ShownCharacter shown_character(std::string_view text, std::size_t i);

// The whole text so shown; line feeds are kept when `keep_line_feeds`.
std::string printable_text(std::string_view text, bool keep_line_feeds = false);

}  // namespace scenfuzz
