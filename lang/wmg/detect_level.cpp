#include "lang/wmg/detect_level.hpp"

#include <algorithm>
#include <string_view>

#include "lang/line_break.hpp"

namespace scenfuzz::wmg {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::size_t skip_blanks(std::string_view line, std::size_t at) {
  while (at < line.size() && is_blank(line[at])) ++at;
  return at;
}

bool starts_with_scenery_elements(std::string_view line) {
  std::size_t at = skip_blanks(line, 0);
  constexpr std::string_view kFirst = "SCENERY";
  constexpr std::string_view kSecond = "ELEMENTS";
  if (line.substr(at, kFirst.size()) != kFirst) return false;
  std::size_t after_first = at + kFirst.size();
  std::size_t second = skip_blanks(line, after_first);
  if (second == after_first) return false;
  if (line.substr(second, kSecond.size()) != kSecond) return false;
  // "ELEMENTS" must end there: followed by nothing, a blank or a colon.
  std::size_t end = second + kSecond.size();
  return end == line.size() || is_blank(line[end]) || line[end] == ':';
}

}  // namespace

int detect_wmg_level(const SourceFile& file) {
  std::string_view text = file.text();
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = find_line_break(text, start);
    if (starts_with_scenery_elements(text.substr(start, end - start))) return 2;
    start = end + std::max<std::size_t>(line_break_width(text, end), 1);
  }
  return 1;
}

}  // namespace scenfuzz::wmg
