#include "lang/diagnostic.hpp"

#include <algorithm>

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

}  // namespace

std::string format_diagnostic(const SourceFile& file, const Diagnostic& diagnostic) {
  const SourceLocation& at = diagnostic.location;
  std::string out = file.path();
  if (at.known()) out += ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
  out += std::string(": ") + severity_name(diagnostic.severity) + ": " + diagnostic.message + "\n";
  if (!at.known()) return out;

  std::string_view line = file.line_text(at.line);
  out += "  ";
  out += line;
  out += "\n  ";
  // Tabs are copied so the caret lines up with what a terminal shows above it.
  std::uint32_t column = 1;
  std::size_t i = 0;
  for (; i < line.size() && column < at.column; ++i) {
    if (is_continuation_byte(line[i])) continue;
    out += line[i] == '\t' ? '\t' : ' ';
    ++column;
  }
  out += '^';
  // Underline the rest of the span while it stays on this line.
  std::size_t line_start = at.offset >= i ? at.offset - i : 0;
  std::size_t span_end = std::min<std::size_t>(at.end_offset(), line_start + line.size());
  for (std::size_t b = at.offset + 1; b < span_end; ++b)
    if (b - line_start < line.size() && !is_continuation_byte(line[b - line_start])) out += '~';
  out += "\n";
  return out;
}

std::string format_diagnostics(const SourceFile& file, const Diagnostics& diagnostics) {
  std::string out;
  for (const Diagnostic& d : diagnostics.all()) out += format_diagnostic(file, d);
  return out;
}

}  // namespace scenfuzz
