// Text of a trace's picture, in the picture's pixels: every <text> carries its own x, y,
// font-size and weight (no transform, no anchor), so that its box is the one the placer
// reserved and a test can read it back.
#include <algorithm>
#include <cmath>
#include <string>

#include "physics/map/svg_writing.hpp"
#include "physics/trace/trace_svg_parts.hpp"

namespace scenfuzz {
namespace {

constexpr std::string_view ellipsis = "...";

// The longest start of `word` that fits `width` with an ellipsis after it.
std::string cut(std::string_view word, const TextFont& font, double width) {
  std::string out;
  for (const char c : word) {
    if (estimated_text_width(out + c + std::string(ellipsis), font) > width) break;
    out += c;
  }
  // Never end inside a UTF-8 sequence.
  while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0x80) != 0) out.pop_back();
  return out + std::string(ellipsis);
}

}  // namespace

void append_text(std::string& out, const PlacedLabel& label, std::string_view text,
                 const TextFont& font, std::string_view colour) {
  out += "<text class=\"trace-text\"";
  append_attribute(out, "x", label.x);
  append_attribute(out, "y", label.baseline);
  append_attribute(out, "font-size", font.size);
  if (font.bold) out += " font-weight=\"bold\"";
  append_attribute(out, "fill", colour);
  out += '>';
  append_escaped(out, text);
  out += "</text>\n";
}

void append_leader(std::string& out, double x, double y, const PixelBox& label) {
  const double to_x = std::clamp(x, label.left, label.right);
  const double to_y = std::clamp(y, label.top, label.bottom);
  if (std::hypot(to_x - x, to_y - y) < 14) return;
  out += "<line class=\"trace-leader\"";
  append_attribute(out, "x1", x);
  append_attribute(out, "y1", y);
  append_attribute(out, "x2", to_x);
  append_attribute(out, "y2", to_y);
  out += "/>\n";
}

std::vector<std::string> wrapped(std::string_view text, const TextFont& font, double width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t space = text.find(' ', at);
    const std::string_view word =
        text.substr(at, space == std::string_view::npos ? std::string_view::npos : space - at);
    at = space == std::string_view::npos ? text.size() : space + 1;
    if (word.empty()) continue;
    const std::string candidate = line.empty() ? std::string(word) : line + " " + std::string(word);
    if (estimated_text_width(candidate, font) <= width) {
      line = candidate;
      continue;
    }
    if (!line.empty()) lines.push_back(line);
    line = estimated_text_width(word, font) <= width ? std::string(word) : cut(word, font, width);
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string fitted(std::string_view text, const TextFont& font, double width) {
  return estimated_text_width(text, font) <= width ? std::string(text) : cut(text, font, width);
}

}  // namespace scenfuzz
