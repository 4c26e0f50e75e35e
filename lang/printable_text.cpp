#include "lang/printable_text.hpp"

namespace scenfuzz {

namespace {

bool in(unsigned char c, int low, int high) { return c >= low && c <= high; }

// The length of the well-formed, printable UTF-8 sequence of two or more bytes at text[i], or 0.
// Overlong forms, surrogates, code points past U+10FFFF and the C1 controls (U+0080 to U+009F,
// which terminals obey as escape codes) do not count.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  auto byte = [&](std::size_t k) -> unsigned char {
    return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0;
  };
  auto continuation = [&](std::size_t k) { return in(byte(k), 0x80, 0xBF); };
  unsigned char lead = byte(0);
  if (lead == 0xC2) return in(byte(1), 0xA0, 0xBF) ? 2 : 0;
  if (in(lead, 0xC3, 0xDF)) return continuation(1) ? 2 : 0;
  if (in(lead, 0xE0, 0xEF)) {
    int low = lead == 0xE0 ? 0xA0 : 0x80;
    int high = lead == 0xED ? 0x9F : 0xBF;
    return in(byte(1), low, high) && continuation(2) ? 3 : 0;
  }
  if (in(lead, 0xF0, 0xF4)) {
    int low = lead == 0xF0 ? 0x90 : 0x80;
    int high = lead == 0xF4 ? 0x8F : 0xBF;
    return in(byte(1), low, high) && continuation(2) && continuation(3) ? 4 : 0;
  }
  return 0;
}

std::string hex_escape(unsigned char c) {
  constexpr const char* kDigits = "0123456789ABCDEF";
  return std::string("\\x") + kDigits[c >> 4] + kDigits[c & 0xF];
}

}  // namespace

ShownCharacter shown_character(std::string_view text, std::size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  if (c == '\t' || in(c, 0x20, 0x7E)) return {std::string(1, text[i]), 1, 1, false};
  if (std::size_t length = utf8_sequence_length(text, i))
    return {std::string(text.substr(i, length)), length, 1, false};
  return {hex_escape(c), 1, 4, true};
}

std::string printable_text(std::string_view text, bool keep_line_feeds) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    if (keep_line_feeds && text[i] == '\n') {
      out += '\n';
      ++i;
      continue;
    }
    ShownCharacter shown = shown_character(text, i);
    out += shown.text;
    i += shown.bytes;
  }
  return out;
}

}  // namespace scenfuzz
