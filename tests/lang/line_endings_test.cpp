// Line endings: a scenario file written with LF (Unix), CRLF (Windows) or CR alone (old Mac) line
// endings reads the same, and every position in it (diagnostics, parameters) has the same
// line:column, in both front ends and in the quoted source line under a diagnostic.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/avunit/lexer.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/wmg.hpp"
#include "tests/lang/test_files.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz {
namespace {

struct Ending {
  const char* name;
  const char* text;
};
const Ending kEndings[] = {{"LF", "\n"}, {"CRLF", "\r\n"}, {"CR", "\r"}};

// The text with each of its LF line endings replaced by `ending`.
std::string with_endings(const std::string& lf_text, const std::string& ending) {
  std::string out;
  for (char c : lf_text) {
    if (c == '\n')
      out += ending;
    else
      out += c;
  }
  return out;
}

std::string positions(const std::vector<Parameter>& parameters) {
  std::string out;
  for (const Parameter& parameter : parameters)
    out += parameter.name + "@" + std::to_string(parameter.location.line) + ":" +
           std::to_string(parameter.location.column) + " ";
  return out;
}

// What a front end makes of a file, with the positions that structural equality leaves out.
struct Reading {
  ScenarioTemplate scenario;
  std::string diagnostics;  // formatted: path:line:column, the quoted line and the caret
  std::string parameter_positions;
  bool ok = false;
};

Reading read_avunit(const std::string& path, const std::string& text) {
  SourceFile file(path, text);
  avunit::ParseResult parsed = avunit::parse(file);
  return {parsed.scenario, format_diagnostics(file, parsed.diagnostics),
          positions(parsed.scenario.parameters), parsed.ok()};
}

Reading read_wmg(const std::string& path, const std::string& text) {
  SourceFile file(path, text);
  wmg::ParseResult parsed = wmg::parse(file);
  return {parsed.scenario, format_diagnostics(file, parsed.diagnostics),
          positions(parsed.scenario.parameters), parsed.ok()};
}

template <class Read>
void expect_same_with_every_ending(const std::string& path, const std::string& lf_text, Read read) {
  const Reading lf = read(path, lf_text);
  for (const Ending& ending : kEndings) {
    SCOPED_TRACE(path + " with " + ending.name + " line endings");
    const Reading other = read(path, with_endings(lf_text, ending.text));
    EXPECT_EQ(other.ok, lf.ok);
    EXPECT_EQ(other.scenario, lf.scenario);
    EXPECT_EQ(other.scenario.has_scenario, lf.scenario.has_scenario);
    EXPECT_EQ(other.diagnostics, lf.diagnostics);
    EXPECT_EQ(other.parameter_positions, lf.parameter_positions);
  }
}

std::string read_text(const std::filesystem::path& path) { return test::load(path).text(); }

TEST(LineEndings, EveryAvunitCorpusFileReadsTheSame) {
  auto files = test::files_in(test::corpus_dir(), {".avu", ".scenest"});
  auto golden = test::files_in(test::lang_data_dir() / "golden", {".avu", ".scenest"});
  files.insert(files.end(), golden.begin(), golden.end());
  ASSERT_GT(files.size(), 10u);
  for (const auto& path : files) {
    const std::string text = read_text(path);
    ASSERT_EQ(text.find('\r'), std::string::npos) << path << " is expected to have LF endings";
    expect_same_with_every_ending(path.string(), text, read_avunit);
  }
}

TEST(LineEndings, EveryWmgCorpusFileReadsTheSame) {
  auto files = test::files_in(wmg::test::wmg_corpus_dir(), {".sdl"});
  auto generated = test::files_in(test::lang_data_dir() / "wmg", {".sdl"});
  files.insert(files.end(), generated.begin(), generated.end());
  ASSERT_GT(files.size(), 10u);
  for (const auto& path : files)
    expect_same_with_every_ending(path.string(), read_text(path), read_wmg);
}

// A misspelt name on a line of a real scenario: the same error, at the same line:column and with
// the same quoted line and caret, whatever the line endings.
TEST(LineEndings, AnAvunitErrorIsReportedAtTheSamePlace) {
  std::string text = read_text(test::corpus_dir() / "cut_in_straight.avu");
  const std::string right = "cut_start = (\"east_1\"->cut_s, , cut_speed);";
  const std::string wrong = "cut_start = (\"east_1\"->cut_s, , cut_sped);";
  ASSERT_NE(text.find(right), std::string::npos);
  const auto line = static_cast<std::uint32_t>(
      1 +
      std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(text.find(right)), '\n'));
  text.replace(text.find(right), right.size(), wrong);
  const auto column = static_cast<std::uint32_t>(wrong.find("cut_sped") + 1);
  for (const Ending& ending : kEndings) {
    SCOPED_TRACE(ending.name);
    SourceFile file("cut_in.avu", with_endings(text, ending.text));
    avunit::ParseResult parsed = avunit::parse(file);
    ASSERT_EQ(parsed.diagnostics.error_count(), 1u) << format_diagnostics(file, parsed.diagnostics);
    const Diagnostic& error = parsed.diagnostics.all().front();
    EXPECT_EQ(error.location.line, line);
    EXPECT_EQ(error.location.column, column);
    const std::string report = format_diagnostic(file, error);
    EXPECT_EQ(
        report.rfind(
            "cut_in.avu:" + std::to_string(line) + ":" + std::to_string(column) + ": error: ", 0),
        0u)
        << report;
    EXPECT_NE(report.find("\n  " + wrong + "\n  " + std::string(column - 1, ' ') + "^~~~~~~~\n"),
              std::string::npos)
        << report;
  }
}

TEST(LineEndings, AWmgErrorIsReportedAtTheSamePlace) {
  wmg::test::Parts parts;
  parts.environment =
      "ENVIRONMENT ELEMENTS:\nDO: [E]\nCloudiness [0]\nRainfall [Drizzle: 0]\n"
      "Time of the day [Any]\nIllumination [Day] with [Sun] as light source\n";
  const std::string text = "# a comment first\n" + parts.text();
  std::vector<std::string> reports;
  for (const Ending& ending : kEndings) {
    SCOPED_TRACE(ending.name);
    SourceFile file("bad.sdl", with_endings(text, ending.text));
    wmg::ParseResult parsed = wmg::parse(file);
    ASSERT_TRUE(parsed.diagnostics.has_errors());
    const Diagnostic& error = parsed.diagnostics.all().front();
    EXPECT_EQ(error.location.line, 16u) << format_diagnostics(file, parsed.diagnostics);
    EXPECT_EQ(error.location.column, 11u) << format_diagnostics(file, parsed.diagnostics);
    reports.push_back(format_diagnostics(file, parsed.diagnostics));
  }
  EXPECT_EQ(reports[1], reports[0]);
  EXPECT_EQ(reports[2], reports[0]);
}

// The old-Mac case that used to pass `scenfuzz check` silently: the first line's `//` comment
// ran to the end of the file, so nothing after it was read.
TEST(LineEndings, ACrOnlyFileAfterALeadingCommentIsReadWhole) {
  const std::string text =
      "// a cut-in, saved on an old Mac\r"
      "ego = AV((\"lane_1\"->10, , 5), (\"lane_1\"->90));\r"
      "s = CreateScenario{load(\"straight\"); ego; {}; {}; {};};\r";
  avunit::ParseResult parsed = test::parse_text(text);
  EXPECT_TRUE(parsed.ok());
  EXPECT_TRUE(parsed.scenario.has_scenario);
  EXPECT_EQ(parsed.scenario.map.name, "straight");

  avunit::ParseResult broken = test::parse_text(text + "x = ;\r");
  ASSERT_TRUE(broken.diagnostics.has_errors());
  EXPECT_EQ(broken.diagnostics.all().front().location.line, 4u);
  EXPECT_EQ(broken.diagnostics.all().front().location.column, 5u);
}

TEST(LineEndings, TheLexersCountCrLfAndCrlfAsOneBreakEach) {
  Diagnostics diagnostics;
  SourceFile file("t.avu", "a\r\nb\rc\nd\r\r\ne /* x\ry\r\n */ f # g\rh \"i\rj\"");
  std::vector<avunit::Token> tokens = avunit::tokenize(file, diagnostics);
  // The string "i is unterminated at the CR: j" opens another one on the next line.
  ASSERT_EQ(tokens.size(), 11u);
  const std::uint32_t expected[][2] = {{1, 1}, {2, 1}, {3, 1}, {4, 1},  {6, 1},
                                       {8, 5}, {9, 1}, {9, 3}, {10, 1}, {10, 2}};
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(tokens[i].location.line, expected[i][0]) << i << " " << tokens[i].text;
    EXPECT_EQ(tokens[i].location.column, expected[i][1]) << i << " " << tokens[i].text;
  }
  EXPECT_EQ(tokens[7].kind, avunit::TokenKind::invalid);
  ASSERT_EQ(diagnostics.error_count(), 2u);
  EXPECT_EQ(diagnostics.all()[0].location.line, 9u);
  EXPECT_EQ(diagnostics.all()[1].location.line, 10u);
}

TEST(LineEndings, SourceLinesEndAtCrLfOrCrlf) {
  SourceFile file("t.avu", "a\r\nb\rc\nd\r\r\n\re");
  ASSERT_EQ(file.line_count(), 7u);
  const char* expected[] = {"a", "b", "c", "d", "", "", "e"};
  for (std::uint32_t line = 1; line <= 7; ++line)
    EXPECT_EQ(file.line_text(line), expected[line - 1]) << line;
  EXPECT_EQ(SourceFile("t", "x\r").line_count(), 2u);
  EXPECT_EQ(SourceFile("t", "x\r").line_text(1), "x");
  EXPECT_EQ(SourceFile("t", "").line_count(), 1u);
}

}  // namespace
}  // namespace scenfuzz
