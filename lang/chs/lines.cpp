// Splitting a CH-Scenario file into located lines.
#include "lang/chs/lines.hpp"

#include <cctype>

#include "lang/line_break.hpp"
#include "lang/text_cursor.hpp"

namespace scenfuzz::chs {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

std::uint32_t characters(std::string_view text) {
  std::uint32_t count = 0;
  for (char c : text)
    if (!is_continuation_byte(c)) ++count;
  return count;
}

}  // namespace

SourceLocation Line::at(std::size_t begin, std::size_t count) const {
  begin = std::min(begin, text.size());
  count = std::min(count, text.size() - begin);
  SourceLocation where = start;
  where.column += characters(text.substr(0, begin));
  where.offset += static_cast<std::uint32_t>(begin);
  where.length = static_cast<std::uint32_t>(count);
  return where;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string normalised(std::string_view text) {
  std::string out;
  for (char c : text)
    if (!is_blank(c) && c != '_' && c != '-')
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return out;
}

std::vector<Line> split_lines(const SourceFile& source) {
  std::vector<Line> lines;
  for (std::uint32_t number = 1; number <= source.line_count(); ++number) {
    std::string_view text = source.line_text(number);
    const std::size_t offset = static_cast<std::size_t>(text.data() - source.text().data());
    if (std::size_t hash = text.find('#'); hash != std::string_view::npos)
      text = text.substr(0, hash);
    std::size_t first = 0;
    while (first < text.size() && is_blank(text[first])) ++first;
    std::string_view kept = trimmed(text);
    if (kept.empty()) continue;
    SourceLocation start{number, 1 + characters(text.substr(0, first)),
                         static_cast<std::uint32_t>(offset + first), 0};
    lines.push_back({kept, start});
  }
  return lines;
}

}  // namespace scenfuzz::chs
