// End-to-end tests of `scenfuzz stl`, run as a user would run it: the robustness of a formula on
// a CSV log (worked out by hand here), the per-sample signal, the note that explains a violation,
// the exit codes, and how bad formulas, bad logs and missing files are reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "command_runner.hpp"
#include "lang/number_format.hpp"

namespace {

namespace fs = std::filesystem;
using scenfuzz::format_number;

// The formula of the issue that asked for `scenfuzz stl`.
constexpr const char* kFormula = "G[0:5](x > 0.5 & F[0:2](y < 0.1))";

// x stays above 0.5 and y dips below 0.1 within every 2 s of the first 5 s: satisfied.
//   y < 0.1:        -0.4  -0.2  0.05  -0.1  -0.1  0.1  -0.3  -0.3
//   F[0:2](y<0.1):  0.05  0.05  0.05   0.1   0.1  0.1  -0.3  -0.3
//   x > 0.5:        0.5   0.4   0.3    0.5  0.25  0.5   0.5   0.5
//   the &:          0.05  0.05  0.05   0.1   0.1  0.1  -0.3  -0.3
// G[0:5] at t = 0 is the least of the first six: 0.05. From t = 1 its window reaches t = 6.
constexpr const char* kSatisfiedLog =
    "time,x,y\n0,1,0.5\n1,0.9,0.3\n2,0.8,0.05\n3,1,0.2\n4,0.75,0.2\n5,1,0.0\n6,1,0.4\n7,1,0.4\n";

// The same log with x at t = 4 down to 0.25: the & there is 0.25 - 0.5 = -0.25, the least of
// the window.
constexpr const char* kXDipsLog =
    "time,x,y\n0,1,0.5\n1,0.9,0.3\n2,0.8,0.05\n3,1,0.2\n4,0.25,0.2\n5,1,0.0\n6,1,0.4\n7,1,0.4\n";

// x stays at 1; y stays above 0.1 from t = 1 to t = 4, so F[0:2] at t = 1 (and t = 2) is at best
// y < 0.1 at t = 3: 0.1 - 0.25.
constexpr const char* kYStaysHighLog =
    "time,x,y\n0,1,0.0\n1,1,0.3\n2,1,0.35\n3,1,0.25\n4,1,0.3\n5,1,0.0\n6,1,0.0\n7,1,0.0\n";

// Four samples for windows that run past the end of the log.
constexpr const char* kShortLog = "time,x\n0,1\n1,0.75\n2,0.25\n3,1\n";

using scenfuzz::test::Outcome;

class StlCommandTest : public scenfuzz::test::CommandTest {
 protected:
  Outcome stl(const std::string& formula, const std::string& log_text,
              std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {"stl", "--spec", formula, "--trace",
                                     write("log.csv", log_text)};
    args.insert(args.end(), extra.begin(), extra.end());
    return scenfuzz(args);
  }
};

TEST_F(StlCommandTest, SatisfiedPrintsTheRobustnessAndExitsZero) {
  const Outcome run = stl(kFormula, kSatisfiedLog);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "0.05\n");
  EXPECT_EQ(run.err, "");
}

TEST_F(StlCommandTest, ViolatedPrintsTheRobustnessAndTheResponsibleAtom) {
  const Outcome run = stl(kFormula, kXDipsLog);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, "-0.25\n");
  EXPECT_EQ(run.err,
            "--spec:1:8: note: violated by 'x > 0.5' at t = 4 (its robustness there: -0.25)\n"
            "  G[0:5](x > 0.5 & F[0:2](y < 0.1))\n"
            "         ^~~~~~~\n");
}

TEST_F(StlCommandTest, TheResponsibleAtomMayBeInsideAnEventually) {
  const Outcome run = stl(kFormula, kYStaysHighLog);
  EXPECT_EQ(run.exit_code, 1);
  const std::string robustness = format_number(0.1 - 0.25);
  EXPECT_EQ(run.out, robustness + "\n");
  EXPECT_EQ(run.err, "--spec:1:25: note: violated by 'y < 0.1' at t = 3 (its robustness there: " +
                         robustness +
                         ")\n"
                         "  G[0:5](x > 0.5 & F[0:2](y < 0.1))\n"
                         "                          ^~~~~~~\n");
}

TEST_F(StlCommandTest, UnderANegationTheAtomKeepsItsOwnSign) {
  const Outcome run = stl("~(x > 0.5)", kShortLog);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, "-0.5\n");
  EXPECT_NE(run.err.find("violated by 'x > 0.5' at t = 0 (its robustness there: 0.5)"),
            std::string::npos)
      << run.err;
}

TEST_F(StlCommandTest, SignalPrintsEverySample) {
  const Outcome run = stl(kFormula, kSatisfiedLog, {"--signal"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::string late = format_number(0.1 - 0.4);  // y < 0.1 at t = 6 and 7
  std::string expected = "time,robustness\n0,0.05\n";
  for (int t = 1; t <= 7; ++t) expected += std::to_string(t) + "," + late + "\n";
  EXPECT_EQ(run.out, expected);
  EXPECT_EQ(run.err, "");
}

TEST_F(StlCommandTest, SignalPrintsInfinitiesForEmptyWindows) {
  // G over a window past the end of the log is +inf; F is -inf.
  const Outcome always = stl("G[2:3](x > 0.5)", kShortLog, {"--signal"});
  EXPECT_EQ(always.exit_code, 1);
  EXPECT_EQ(always.out, "time,robustness\n0,-0.25\n1,0.5\n2,inf\n3,inf\n");
  EXPECT_NE(always.err.find("violated by 'x > 0.5' at t = 2"), std::string::npos) << always.err;

  const Outcome eventually = stl("F[2:3](x > 0.5)", kShortLog, {"--signal"});
  EXPECT_EQ(eventually.exit_code, 0) << eventually.err;
  EXPECT_EQ(eventually.out, "time,robustness\n0,0.5\n1,0.5\n2,-inf\n3,-inf\n");
  EXPECT_EQ(eventually.err, "");
}

TEST_F(StlCommandTest, InfiniteRobustnessAtTheStart) {
  const Outcome never = stl("F[10:20](x > 0.5)", kShortLog);
  EXPECT_EQ(never.exit_code, 1);
  EXPECT_EQ(never.out, "-inf\n");
  EXPECT_EQ(never.err,
            "--spec: note: violated with robustness -inf, which no atom gives: a window of F or U "
            "holds no sample (the log ends at t = 3)\n");

  const Outcome vacuous = stl("G[10:20](x > 0.5)", kShortLog);
  EXPECT_EQ(vacuous.exit_code, 0) << vacuous.err;
  EXPECT_EQ(vacuous.out, "inf\n");
}

TEST_F(StlCommandTest, FormulasMayReadTimeAndDottedColumns) {
  const Outcome run =
      stl("G(time >= 2 -> ego.speed < 5)", "time,ego.speed\n0,9\n1,8\n2,4.5\n3,4\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "0.5\n");
}

TEST_F(StlCommandTest, BadFormulaIsReportedAtItsPlaceInTheSpec) {
  const Outcome run = stl("G[0:5](x > 0.5 & F[0:2](y < ))", kSatisfiedLog);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err.rfind("--spec:1:29: error: ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("\n  G[0:5](x > 0.5 & F[0:2](y < ))\n"
                         "                              ^\n"),
            std::string::npos)
      << run.err;
}

TEST_F(StlCommandTest, UnknownColumnListsTheColumns) {
  const Outcome run = stl("G[0:5](x > 0.5 & F[0:2](z < 0.1))", kSatisfiedLog);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err,
            "--spec:1:25: error: no column 'z'; the columns are: time, x, y\n"
            "  G[0:5](x > 0.5 & F[0:2](z < 0.1))\n"
            "                          ^\n");
}

TEST_F(StlCommandTest, MalformedLogIsReportedAtFileLineAndColumn) {
  const Outcome run = stl(kFormula, "time,x,y\n0,1,0.5\n1,abc,0.3\n");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, (dir_ / "log.csv").string() +
                         ":3:3: error: expected a number in column 'x', got 'abc'\n"
                         "  1,abc,0.3\n"
                         "    ^~~\n");
}

TEST_F(StlCommandTest, LogWithoutTimeOrSamples) {
  const Outcome no_time = stl("x > 0", "t,x\n0,1\n");
  EXPECT_EQ(no_time.exit_code, 2);
  EXPECT_NE(no_time.err.find("log.csv:1:1: error: no 'time' column"), std::string::npos)
      << no_time.err;
  const Outcome header_only = stl("x > 0", "time,x\n");
  EXPECT_EQ(header_only.exit_code, 2);
  EXPECT_NE(header_only.err.find("log.csv:1:1: error: no samples"), std::string::npos)
      << header_only.err;
}

TEST_F(StlCommandTest, MissingLogFile) {
  const std::string missing = (dir_ / "missing.csv").string();
  const Outcome run = scenfuzz({"stl", "--spec", "x > 0", "--trace", missing});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "scenfuzz: error: cannot read '" + missing + "': No such file or directory\n");
}

TEST_F(StlCommandTest, BadFormulaIsReportedBeforeTheLogIsRead) {
  const Outcome run =
      scenfuzz({"stl", "--spec", "x >", "--trace", (dir_ / "missing.csv").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.rfind("--spec:1:", 0), 0u) << run.err;
  EXPECT_EQ(run.err.find("cannot read"), std::string::npos) << run.err;
}

TEST_F(StlCommandTest, MissingOptionsAreUsageErrors) {
  const std::string log = write("log.csv", kShortLog);
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"stl"}, {"stl", "--spec", "x > 0"}, {"stl", "--trace", log}}) {
    const Outcome run = scenfuzz(args);
    EXPECT_EQ(run.exit_code, 2) << ::testing::PrintToString(args);
    EXPECT_NE(run.err.find("scenfuzz: error:"), std::string::npos) << run.err;
  }
}

TEST_F(StlCommandTest, HelpDescribesTheOptions) {
  const Outcome run = scenfuzz({"stl", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option : {"--spec", "--trace", "--signal"})
    EXPECT_NE(run.out.find(option), std::string::npos) << option << "\n" << run.out;
  const Outcome top = scenfuzz({"--help"});
  EXPECT_NE(top.out.find("stl"), std::string::npos) << top.out;
}

}  // namespace
