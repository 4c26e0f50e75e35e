// A diagnostic quoting a line that holds NULs, control bytes or malformed UTF-8 shows them as
// `\xNN` rather than sending them to the terminal, and its caret stays under the right character.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/printable_text.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz {
namespace {

using namespace std::string_literals;  // "\0"s keeps its NUL

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(text.substr(start, end - start));
  return lines;
}

// Nothing a terminal would act on: no byte below 0x20 but the line feeds and tabs, and no DEL.
void expect_printable(const std::string& report) {
  for (char c : report) {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_TRUE(byte >= 0x20 || c == '\n' || c == '\t') << "byte " << int(byte) << " in\n"
                                                        << report;
    EXPECT_NE(byte, 0x7F) << report;
  }
}

// The first diagnostic of an AVUnit text, formatted.
std::string first_report(const std::string& text) {
  SourceFile file("t.avu", text);
  avunit::ParseResult parsed = avunit::parse(file);
  EXPECT_FALSE(parsed.diagnostics.all().empty()) << text;
  if (parsed.diagnostics.all().empty()) return "";
  return format_diagnostic(file, parsed.diagnostics.all().front());
}

// The quoted line is report line 2 and the caret line report line 3, both indented by two; the
// caret must sit under the first character of the last `under` in the shown line.
void expect_caret_under(const std::string& report, const std::string& shown_line,
                        const std::string& under, std::size_t tildes) {
  std::vector<std::string> lines = lines_of(report);
  ASSERT_EQ(lines.size(), 3u) << report;
  EXPECT_EQ(lines[1], "  " + shown_line) << report;
  const std::size_t at = shown_line.rfind(under);
  ASSERT_NE(at, std::string::npos) << shown_line;
  // One space per character shown before it (a UTF-8 continuation byte adds none), a tab per tab.
  std::string padding;
  for (char c : shown_line.substr(0, at))
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) padding += c == '\t' ? '\t' : ' ';
  EXPECT_EQ(lines[2], "  " + padding + "^" + std::string(tildes, '~')) << report;
}

TEST(DiagnosticDisplay, AnOffendingNulIsShownEscapedWithTheCaretUnderIt) {
  const std::string report = first_report("a = 1 \0;\n"s);
  expect_printable(report);
  EXPECT_EQ(lines_of(report)[0], "t.avu:1:7: error: unexpected character '\\x00'");
  expect_caret_under(report, "a = 1 \\x00;", "\\x00", 3);
}

TEST(DiagnosticDisplay, EscapedBytesBeforeTheErrorKeepTheCaretAligned) {
  // An escape sequence that would clear the screen, a bell and a NUL inside a string, then an
  // error further along the line.
  const std::string report = first_report("n = \"\x1b[2J\a\0\"; x = ;\n"s);
  expect_printable(report);
  EXPECT_EQ(lines_of(report)[0].rfind("t.avu:1:", 0), 0u);
  expect_caret_under(report, "n = \"\\x1B[2J\\x07\\x00\"; x = ;", ";", 0);
}

TEST(DiagnosticDisplay, MalformedUtf8IsEscapedAndWellFormedUtf8Kept) {
  // "é" is well-formed (one column); 0xFF is no UTF-8 at all; 0x80 is a continuation byte with
  // no lead; 0xC2 0x9B is the C1 control CSI, which terminals obey.
  const std::string report = first_report("s = \"\xC3\xA9\xFF\x80\xC2\x9B\"; y = ;\n");
  expect_printable(report);
  expect_caret_under(report, "s = \"\xC3\xA9\\xFF\\x80\\xC2\\x9B\"; y = ;", ";", 0);
}

TEST(DiagnosticDisplay, TabsStayTabsInBothLines) {
  const std::string report = first_report("\tn = \"\t\x01\"; q = ;\n");
  expect_printable(report);
  expect_caret_under(report, "\tn = \"\t\\x01\"; q = ;", ";", 0);
  EXPECT_EQ(lines_of(report)[2].substr(0, 3), "  \t");
}

TEST(DiagnosticDisplay, TheUnderlineCoversEscapedBytesInTheSpan) {
  SourceFile file("t.avu",
                  "ab\x01\x02"
                  "cd\n");
  Diagnostic diagnostic;
  diagnostic.location = SourceLocation{1, 2, 1, 4};  // "b\x01\x02c"
  diagnostic.message = "span";
  const std::string report = format_diagnostic(file, diagnostic);
  expect_printable(report);
  expect_caret_under(report, "ab\\x01\\x02cd", "b", 9);
}

TEST(DiagnosticDisplay, AMessageQuotingABadByteIsEscapedToo) {
  Diagnostic diagnostic;
  diagnostic.location = SourceLocation{1, 1, 0, 1};
  diagnostic.message = "unexpected character '\x1b'\nsecond line";
  const std::string report = format_diagnostic(SourceFile("t.avu", "\x1b\n"), diagnostic);
  expect_printable(report);
  EXPECT_EQ(report,
            "t.avu:1:1: error: unexpected character '\\x1B'\nsecond line\n  \\x1B\n  ^~~~\n");
}

TEST(DiagnosticDisplay, WmgDiagnosticsAreEscapedToo) {
  SourceFile file("t.sdl", "VERSION: 1.0\x00\x01\nAUTHOR: 'a'\n"s);
  wmg::ParseResult parsed = wmg::parse(file);
  ASSERT_TRUE(parsed.diagnostics.has_errors());
  const std::string report = format_diagnostic(file, parsed.diagnostics.all().front());
  expect_printable(report);
  expect_caret_under(report, "VERSION: 1.0\\x00\\x01", "\\x00", 3);
}

TEST(PrintableText, KeepsWhatATerminalShowsAsItIs) {
  EXPECT_EQ(printable_text("plain, \t tabbed, \xE2\x80\x9Cquoted\xE2\x80\x9D \xF0\x9F\x9A\x97"),
            "plain, \t tabbed, \xE2\x80\x9Cquoted\xE2\x80\x9D \xF0\x9F\x9A\x97");
  EXPECT_EQ(printable_text("a\nb"), "a\\x0Ab");
  EXPECT_EQ(printable_text("a\nb", true), "a\nb");
  EXPECT_EQ(printable_text("\r\x7F"), "\\x0D\\x7F");
  // Overlong, surrogate and truncated sequences.
  EXPECT_EQ(printable_text("\xC0\xAF \xED\xA0\x80 \xE2\x80"),
            "\\xC0\\xAF \\xED\\xA0\\x80 \\xE2\\x80");
}

}  // namespace
}  // namespace scenfuzz
