#include "lang/diagnostic.hpp"

#include <algorithm>
#include <string_view>

#include "lang/printable_text.hpp"

namespace scenfuzz {

void Diagnostics::error(SourceLocation where, std::string message) {
  if (too_many_errors()) return;
  ++errors_;
  items_.push_back({Severity::error, where, std::move(message)});
  if (too_many_errors())
    items_.push_back({Severity::note, where, "too many errors; stopping here"});
}

void Diagnostics::warning(SourceLocation where, std::string message) {
  items_.push_back({Severity::warning, where, std::move(message)});
}

void Diagnostics::note(SourceLocation where, std::string message) {
  items_.push_back({Severity::note, where, std::move(message)});
}

namespace {

const char* severity_name(Severity severity) {
  switch (severity) {
    case Severity::error: return "error";
    case Severity::warning: return "warning";
    case Severity::note: return "note";
  }
  return "error";
}

bool is_continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The source line, shown safely (printable_text.hpp), and under it a caret at the location's
// column and tildes under the rest of its span on this line. Every character before the caret
// is matched by padding of its shown width, so the caret stays under it whatever was escaped.
std::string quoted_line(const SourceFile& file, const SourceLocation& at) {
  const std::string_view line = file.line_text(at.line);
  std::string shown_line = "  ";
  std::string carets = "  ";
  // Columns count as the lexers count them (text_cursor.hpp): a byte that is not a UTF-8
  // continuation byte starts a new column.
  std::uint32_t column = 1;
  std::size_t i = 0;
  while (i < line.size() && column < at.column) {
    ShownCharacter shown = shown_character(line, i);
    shown_line += shown.text;
    // Tabs are copied so the caret lines up with what a terminal shows above it.
    carets += shown.text == "\t" ? std::string("\t") : std::string(shown.width, ' ');
    i += shown.bytes;
    if (i < line.size() && !is_continuation_byte(line[i])) ++column;
  }
  // Underline the rest of the span while it stays on this line.
  // line_text() is a view into the file's text (or empty past its last line).
  const auto line_start =
      line.empty() ? std::size_t{0} : static_cast<std::size_t>(line.data() - file.text().data());
  const std::size_t span_end =
      at.end_offset() > line_start
          ? std::min<std::size_t>(at.end_offset() - line_start, line.size())
          : 0;
  carets += '^';
  for (bool first = true; i < line.size(); first = false) {
    ShownCharacter shown = shown_character(line, i);
    shown_line += shown.text;
    if (i < span_end || first) carets += std::string(shown.width - (first ? 1 : 0), '~');
    i += shown.bytes;
  }
  return shown_line + "\n" + carets + "\n";
}

}  // namespace

std::string format_diagnostic(const SourceFile& file, const Diagnostic& diagnostic) {
  const SourceLocation& at = diagnostic.location;
  std::string out = file.path();
  if (at.known()) out += ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
  // A message may quote the file (an unexpected character): it is shown safely too.
  out += std::string(": ") + severity_name(diagnostic.severity) + ": " +
         printable_text(diagnostic.message, true) + "\n";
  if (!at.known()) return out;
  return out + quoted_line(file, at);
}

std::string format_diagnostics(const SourceFile& file, const Diagnostics& diagnostics) {
  std::string out;
  for (const Diagnostic& d : diagnostics.all()) out += format_diagnostic(file, d);
  return out;
}

}  // namespace scenfuzz
