// Tests of the CSV log reader behind `scenfuzz stl --trace`: what it accepts (quoting, CRLF,
// blanks around numbers, trailing blank lines), each error it reports and where, and the
// SignalSource that lets a formula name the columns.
#include "oracle/csv_signals.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

struct Read {
  std::optional<CsvSignals> signals;
  Diagnostics diagnostics;
  std::string printed;  // the diagnostics as the command line prints them
};

Read read(const std::string& text) {
  const SourceFile file("log.csv", text);
  Read result;
  result.signals = read_csv_signals(file, result.diagnostics);
  result.printed = format_diagnostics(file, result.diagnostics);
  return result;
}

// The one error a malformed log gives: its message and where it points.
struct Error {
  std::string message;
  std::uint32_t line = 0, column = 0, length = 0;
};

Error only_error(const std::string& text) {
  const Read result = read(text);
  EXPECT_FALSE(result.signals) << text;
  EXPECT_EQ(result.diagnostics.error_count(), 1u) << result.printed;
  for (const Diagnostic& d : result.diagnostics.all())
    if (d.severity == Severity::error)
      return {d.message, d.location.line, d.location.column, d.location.length};
  return {};
}

TEST(CsvSignals, ReadsTimeAndColumns) {
  const Read result = read("time,x,y\n0,1,2.5\n0.1,-3,4e-2\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_EQ(result.printed, "");
  EXPECT_THAT(result.signals->time, ElementsAre(0.0, 0.1));
  EXPECT_THAT(result.signals->columns.at("x"), ElementsAre(1.0, -3.0));
  EXPECT_THAT(result.signals->columns.at("y"), ElementsAre(2.5, 0.04));
  EXPECT_EQ(result.signals->columns.count("time"), 0u);
}

TEST(CsvSignals, TimeNeedNotBeTheFirstColumn) {
  const Read result = read("x,time\n5,0\n6,1\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_THAT(result.signals->time, ElementsAre(0.0, 1.0));
  EXPECT_THAT(result.signals->columns.at("x"), ElementsAre(5.0, 6.0));
}

TEST(CsvSignals, QuotedFieldsMayHoldCommasAndDoubledQuotes) {
  const Read result = read("time,\"a,b\",\"say \"\"hi\"\"\"\n\"0\",\"1\",\"2\"\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_THAT(result.signals->columns.at("a,b"), ElementsAre(1.0));
  EXPECT_THAT(result.signals->columns.at("say \"hi\""), ElementsAre(2.0));
  EXPECT_THAT(result.signals->time, ElementsAre(0.0));
}

TEST(CsvSignals, AcceptsCrlfAndTrailingBlankLines) {
  for (const std::string text :
       {"time,x\r\n0,1\r\n1,2\r\n", "time,x\r\n0,1\r\n1,2", "time,x\n0,1\n1,2\n\n",
        "time,x\n0,1\n1,2\n  \n\n", "time,x\r\n0,1\r\n1,2\r\n\r\n"}) {
    const Read result = read(text);
    ASSERT_TRUE(result.signals) << text << result.printed;
    EXPECT_THAT(result.signals->time, ElementsAre(0.0, 1.0)) << text;
    EXPECT_THAT(result.signals->columns.at("x"), ElementsAre(1.0, 2.0)) << text;
  }
}

TEST(CsvSignals, AcceptsBlanksAroundNumbersAndNames) {
  const Read result = read("time , x\n 0 ,\t1.5 \n1, \" 2 \"\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_THAT(result.signals->time, ElementsAre(0.0, 1.0));
  EXPECT_THAT(result.signals->columns.at("x"), ElementsAre(1.5, 2.0));
}

TEST(CsvSignals, AcceptsALeadingPlusAndAByteOrderMark) {
  const Read result = read("\xEF\xBB\xBFtime,x\n0,+1\n1,-2\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_THAT(result.signals->columns.at("x"), ElementsAre(1.0, -2.0));
}

TEST(CsvSignals, NumbersReadBackExactly) {
  const Read result = read("time,x\n0,0.1\n1,553090.1\n2,1e-07\n3,-0\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_THAT(result.signals->columns.at("x"), ElementsAre(0.1, 553090.1, 1e-07, 0.0));
}

TEST(CsvSignals, MissingTimeColumn) {
  const Error error = only_error("t,x\n0,1\n");
  EXPECT_THAT(error.message, HasSubstr("no 'time' column"));
  EXPECT_EQ(error.line, 1u);
  EXPECT_EQ(error.column, 1u);
  EXPECT_EQ(error.length, 3u);  // the whole header line
}

TEST(CsvSignals, MissingTimeColumnExplainsCaseAndHeaderlessFiles) {
  EXPECT_THAT(only_error("Time,x\n0,1\n").message, HasSubstr("'Time' is not 'time'"));
  EXPECT_THAT(only_error("0,1\n1,2\n").message, HasSubstr("holds numbers, not names"));
}

TEST(CsvSignals, DuplicateColumnPointsAtBothNames) {
  const Read result = read("time,x,y,x\n0,1,2,3\n");
  EXPECT_FALSE(result.signals);
  ASSERT_EQ(result.diagnostics.all().size(), 2u) << result.printed;
  const Diagnostic& error = result.diagnostics.all()[0];
  EXPECT_EQ(error.severity, Severity::error);
  EXPECT_EQ(error.message, "duplicate column 'x'");
  EXPECT_EQ(error.location.column, 10u);
  const Diagnostic& note = result.diagnostics.all()[1];
  EXPECT_EQ(note.severity, Severity::note);
  EXPECT_EQ(note.location.column, 6u);
  EXPECT_EQ(result.printed,
            "log.csv:1:10: error: duplicate column 'x'\n"
            "  time,x,y,x\n"
            "           ^\n"
            "log.csv:1:6: note: 'x' is first named here\n"
            "  time,x,y,x\n"
            "       ^\n");
}

TEST(CsvSignals, EmptyColumnName) {
  const Error error = only_error("time,,y\n0,1,2\n");
  EXPECT_THAT(error.message, HasSubstr("empty column name"));
  EXPECT_EQ(error.column, 6u);
}

TEST(CsvSignals, RowWithTooFewFieldsPointsAtItsEnd) {
  const Error error = only_error("time,x,y\n0,1,2\n1,2\n");
  EXPECT_EQ(error.message, "this row has 2 fields; expected 3: time, x, y");
  EXPECT_EQ(error.line, 3u);
  EXPECT_EQ(error.column, 4u);
}

TEST(CsvSignals, RowWithTooManyFieldsPointsAtTheExtraOnes) {
  const Error error = only_error("time,x\n0,1\n1,2,3,4\n");
  EXPECT_EQ(error.message, "this row has 4 fields; expected 2: time, x");
  EXPECT_EQ(error.line, 3u);
  EXPECT_EQ(error.column, 5u);
  EXPECT_EQ(error.length, 3u);  // "3,4"
}

TEST(CsvSignals, RaggedRowsAreEachReported) {
  const Read result = read("time,x\n0\n1,2,3\n2,3\n");
  EXPECT_FALSE(result.signals);
  EXPECT_EQ(result.diagnostics.error_count(), 2u) << result.printed;
}

TEST(CsvSignals, NonNumericFieldNamesTheColumn) {
  const Read result = read("time,speed\n0,1\n1,fast\n");
  EXPECT_FALSE(result.signals);
  EXPECT_EQ(result.printed,
            "log.csv:3:3: error: expected a number in column 'speed', got 'fast'\n"
            "  1,fast\n"
            "    ^~~~\n");
}

TEST(CsvSignals, PartlyNumericFieldIsRejected) {
  EXPECT_EQ(only_error("time,x\n0,1.5m\n").message, "expected a number in column 'x', got '1.5m'");
  EXPECT_EQ(only_error("time,x\n0,1 2\n").message, "expected a number in column 'x', got '1 2'");
  EXPECT_EQ(only_error("time,x\n0,0x10\n").message, "expected a number in column 'x', got '0x10'");
}

TEST(CsvSignals, DecimalCommaIsNotANumber) {
  // A locale's decimal comma would be two fields unquoted, and is no number quoted.
  EXPECT_EQ(only_error("time,x\n0,\"1,5\"\n").message,
            "expected a number in column 'x', got '1,5'");
}

TEST(CsvSignals, AColumnOfTextIsReportedOnce) {
  const Read result = read("time,x\n0,a\n1,b\n2,c\n");
  EXPECT_FALSE(result.signals);
  EXPECT_EQ(result.diagnostics.error_count(), 1u) << result.printed;
  EXPECT_THAT(result.printed, HasSubstr("column 'x' has 2 more fields that are not"));
}

TEST(CsvSignals, EmptyFieldIsNotANumber) {
  const Error error = only_error("time,x\n0,\n");
  EXPECT_EQ(error.message, "empty field in column 'x': expected a number");
  EXPECT_EQ(error.column, 3u);
}

TEST(CsvSignals, NanAndInfinityAreRejected) {
  for (const std::string word : {"nan", "NaN", "inf", "-inf", "infinity", "-Infinity"}) {
    const Error error = only_error("time,x\n0," + word + "\n");
    EXPECT_EQ(error.message, "expected a finite number in column 'x', got '" + word + "'");
    EXPECT_EQ(error.line, 2u);
    EXPECT_EQ(error.column, 3u);
  }
  EXPECT_EQ(only_error("time,x\nnan,1\n").message,
            "expected a finite number in column 'time', got 'nan'");
}

TEST(CsvSignals, NumbersBeyondADoubleAreRejected) {
  EXPECT_THAT(only_error("time,x\n0,1e999\n").message, HasSubstr("out of the range of a double"));
}

TEST(CsvSignals, TimesMustIncreaseStrictly) {
  const Error repeated = only_error("time,x\n0,1\n0.5,2\n0.5,3\n");
  EXPECT_EQ(repeated.message,
            "time 0.5 does not come after the previous row's 0.5: times must increase strictly");
  EXPECT_EQ(repeated.line, 4u);
  EXPECT_EQ(repeated.column, 1u);
  const Error backwards = only_error("time,x\n1,1\n0,2\n");
  EXPECT_EQ(backwards.line, 3u);
  EXPECT_THAT(backwards.message, HasSubstr("time 0 does not come after the previous row's 1"));
}

TEST(CsvSignals, NegativeTimesAreFine) {
  const Read result = read("time,x\n-1,1\n0,2\n");
  ASSERT_TRUE(result.signals) << result.printed;
  EXPECT_THAT(result.signals->time, ElementsAre(-1.0, 0.0));
}

TEST(CsvSignals, HeaderOnly) {
  for (const std::string text : {"time,x\n", "time,x", "time,x\n\n"}) {
    const Error error = only_error(text);
    EXPECT_THAT(error.message, HasSubstr("no samples")) << text;
    EXPECT_EQ(error.line, 1u);
  }
}

TEST(CsvSignals, EmptyFile) {
  for (const std::string text : {"", "\n", "\r\n\r\n"}) {
    const Error error = only_error(text);
    EXPECT_THAT(error.message, HasSubstr("empty file")) << text;
    EXPECT_EQ(error.line, 1u);
    EXPECT_EQ(error.column, 1u);
  }
}

TEST(CsvSignals, BlankFirstLine) {
  EXPECT_THAT(only_error("\ntime,x\n0,1\n").message, HasSubstr("the first line is blank"));
}

TEST(CsvSignals, BlankLineBetweenRows) {
  const Error error = only_error("time,x\n0,1\n\n1,2\n");
  EXPECT_THAT(error.message, HasSubstr("blank line between rows"));
  EXPECT_EQ(error.line, 3u);
}

TEST(CsvSignals, UnterminatedQuotePointsAtTheOpeningQuote) {
  const Error error = only_error("time,x\n0,\"1\n1,2\n");
  EXPECT_EQ(error.message, "this quoted field has no closing '\"'");
  EXPECT_EQ(error.line, 2u);
  EXPECT_EQ(error.column, 3u);
}

TEST(CsvSignals, TextAfterAClosingQuote) {
  const Error error = only_error("time,x\n0,\"1\"5\n");
  EXPECT_EQ(error.message, "expected ',' or the end of the line after a quoted field");
  EXPECT_EQ(error.column, 6u);
}

TEST(CsvSignals, QuoteInsideAnUnquotedField) {
  const Error error = only_error("time,x\n0,1\"5\n");
  EXPECT_THAT(error.message, HasSubstr("inside a field that does not start with one"));
  EXPECT_EQ(error.column, 4u);
}

TEST(CsvSignals, QuotedFieldMaySpanLines) {
  // The line break belongs to the name; the next row's line numbers still count it.
  const Read result = read("time,\"a\nb\"\n0,1\n1,x\n");
  EXPECT_FALSE(result.signals);
  ASSERT_EQ(result.diagnostics.error_count(), 1u) << result.printed;
  EXPECT_EQ(result.diagnostics.all()[0].location.line, 4u);
}

TEST(CsvSignals, ColumnsCountCharactersNotBytes) {
  const Read result = read("time,é,x\n0,1,bad\n");
  EXPECT_FALSE(result.signals);
  ASSERT_EQ(result.diagnostics.error_count(), 1u);
  EXPECT_EQ(result.diagnostics.all()[0].location.column, 5u);
  const Read header = read("time,é,é\n0,1,2\n");
  ASSERT_FALSE(header.diagnostics.all().empty());
  EXPECT_EQ(header.diagnostics.all()[0].location.column, 8u);
}

TEST(CsvSignals, ErrorsInSeveralRowsAreAllReported) {
  const Read result = read("time,x,y\n0,a,1\n1,2,b\n2,3\n");
  EXPECT_FALSE(result.signals);
  EXPECT_EQ(result.diagnostics.error_count(), 3u) << result.printed;
}

// ---- the signal source ----------------------------------------------------------------------

SpecTerm signal_term(const std::string& name, std::vector<SpecTerm> operands = {}) {
  SpecTerm term;
  term.kind = TermKind::signal;
  term.name = name;
  term.operands = std::move(operands);
  term.location = SourceLocation{1, 3, 2, static_cast<std::uint32_t>(name.size())};
  return term;
}

SpecTerm number_term(double value) {
  SpecTerm term;
  term.kind = TermKind::number;
  term.value = constant_value(value);
  return term;
}

CsvSignals example_signals() {
  const Read result = read("time,x,ego.speed,stoplineAhead\n0,1,10,5\n1,2,11,3\n");
  EXPECT_TRUE(result.signals) << result.printed;
  return *result.signals;
}

TEST(CsvSignalSource, NamesReadColumns) {
  const CsvSignals signals = example_signals();
  const SignalSource source = csv_signal_source(signals);
  EXPECT_THAT(source.time, ElementsAre(0.0, 1.0));
  const SignalValues x = source.leaf(signal_term("x"));
  EXPECT_THAT(x.values, ElementsAre(1.0, 2.0));
  EXPECT_FALSE(x.discrete);
  EXPECT_THAT(source.leaf(signal_term("ego.speed")).values, ElementsAre(10.0, 11.0));
  EXPECT_THAT(source.leaf(signal_term("time")).values, ElementsAre(0.0, 1.0));
}

TEST(CsvSignalSource, DistancePredicateReadsItsColumn) {
  const CsvSignals signals = example_signals();
  const SignalSource source = csv_signal_source(signals);
  EXPECT_THAT(source.leaf(signal_term("stoplineAhead", {number_term(2)})).values,
              ElementsAre(5.0, 3.0));
}

TEST(CsvSignalSource, UnknownColumnListsTheColumns) {
  const CsvSignals signals = example_signals();
  const SignalSource source = csv_signal_source(signals);
  try {
    source.leaf(signal_term("z"));
    FAIL() << "no OracleError";
  } catch (const OracleError& error) {
    EXPECT_STREQ(error.what(), "no column 'z'; the columns are: time, ego.speed, stoplineAhead, x");
    EXPECT_EQ(error.location().column, 3u);
    EXPECT_EQ(error.location().length, 1u);
  }
}

TEST(CsvSignalSource, SignalFunctionsNeedASimulatedTrace) {
  const CsvSignals signals = example_signals();
  const SignalSource source = csv_signal_source(signals);
  try {
    source.leaf(signal_term("dis", {signal_term("x"), signal_term("x")}));
    FAIL() << "no OracleError";
  } catch (const OracleError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'dis' needs a simulated trace"));
    EXPECT_THAT(error.what(), HasSubstr("time, ego.speed, stoplineAhead, x"));
  }
}

TEST(CsvSignalSource, EvaluatesAFormula) {
  const CsvSignals signals = example_signals();
  Formula formula;
  formula.kind = FormulaKind::comparison;
  formula.compare = CompareOp::greater;
  formula.terms = {signal_term("x"), number_term(1.5)};
  EXPECT_THAT(robustness_signal(formula, csv_signal_source(signals)), ElementsAre(-0.5, 0.5));
}

}  // namespace
}  // namespace scenfuzz
