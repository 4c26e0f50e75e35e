// The report's inline SVG charts: round axis ticks, the best-so-far step line with the zero line
// and run starts, the trend's bars by status, and escaped text.
#include "fuzz/campaign/campaign_report_svg.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

namespace scenfuzz {
namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t found = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++found;
  return found;
}

TEST(AxisTicksTest, RoundNumbersWithinTheRange) {
  EXPECT_EQ(axis_ticks(0, 100, 5), (std::vector<double>{0, 20, 40, 60, 80, 100}));
  EXPECT_EQ(axis_ticks(0, 7, 6), (std::vector<double>{0, 2, 4, 6}));
  EXPECT_EQ(axis_ticks(-2.3, 1.2, 5), (std::vector<double>{-2, -1, 0, 1}));
  EXPECT_EQ(axis_ticks(-2.3, 1.2, 8), (std::vector<double>{-2, -1.5, -1, -0.5, 0, 0.5, 1}));
  EXPECT_EQ(axis_ticks(0, 2000, 6), (std::vector<double>{0, 500, 1000, 1500, 2000}));
}

ReportSeed seed_with(std::vector<BestSoFar> best, std::size_t simulations) {
  ReportSeed seed;
  seed.seed.path = "a.avu";
  seed.simulations = simulations;
  seed.best = std::move(best);
  seed.run_starts = {{1, 0}, {2, simulations / 2}};
  return seed;
}

TEST(RobustnessChartTest, AStepLineFromTheFirstJudgedSimulationToTheLast) {
  const std::string svg = robustness_chart_svg(seed_with({{1, 3}, {40, 1}, {70, -1}}, 100), "t");
  // One path: moves to the first point, then only horizontal and vertical steps, ending at the
  // last simulation (x = 100 is the plot's right edge: 640 - 20).
  const std::regex path(
      "<path class=\"best-so-far\" d=\"(M[-0-9. ]+(?: H[-0-9.]+ V[-0-9.]+)*) H620\"");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(svg, match, path)) << svg;
  EXPECT_EQ(count(match[1].str(), " H"), 2u);
  // The zero line, marked, with the violating side tinted; both runs' starts; axis labels.
  EXPECT_EQ(count(svg, "class=\"zero-line\""), 1u);
  EXPECT_EQ(count(svg, "class=\"violated-region\""), 1u);
  EXPECT_NE(svg.find("0: violated below"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"run-start\""), 2u);
  EXPECT_NE(svg.find(">run 2</text>"), std::string::npos);
  EXPECT_NE(svg.find(">simulations of this seed</text>"), std::string::npos);
  EXPECT_NE(svg.find(">best robustness</text>"), std::string::npos);
  EXPECT_NE(svg.find(">best -1</text>"), std::string::npos);
  // Ticks: 0 and 100 simulations among them.
  EXPECT_NE(svg.find(">0</text>"), std::string::npos);
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);
}

TEST(RobustnessChartTest, RunStartsTooCloseForTheirLabelsAreMarkedButNotAllLabelled) {
  ReportSeed seed = seed_with({{1, 1}}, 1000);
  seed.run_starts.clear();
  for (std::int64_t run = 1; run <= 100; ++run)
    seed.run_starts.push_back({run, static_cast<std::size_t>(run - 1) * 10});
  const std::string svg = robustness_chart_svg(seed, "t");
  EXPECT_EQ(count(svg, "class=\"run-start\""), 100u);
  const std::size_t labels = count(svg, ">run ");
  EXPECT_GE(labels, 5u);
  EXPECT_LE(labels, 14u);  // 548 pixels of plot, a label per 44 at most
}

TEST(RobustnessChartTest, InfinitiesStayInsideThePlot) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::string svg = robustness_chart_svg(seed_with({{1, inf}, {5, 2}, {9, -inf}}, 10), "t");
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf\""), std::string::npos);  // no infinite coordinate
  EXPECT_NE(svg.find(">best -inf</text>"), std::string::npos);
}

TEST(RobustnessChartTest, ASeedWithoutJudgedSimulationsSaysSo) {
  const std::string svg = robustness_chart_svg(seed_with({}, 0), "t");
  EXPECT_NE(svg.find("no judged simulation yet"), std::string::npos);
  EXPECT_EQ(svg.find("best-so-far"), std::string::npos);
}

TEST(RobustnessChartTest, TheTitleIsEscaped) {
  const std::string svg = robustness_chart_svg(seed_with({{1, 1}}, 1), "seeds/<cut> & \"co\".avu");
  EXPECT_NE(svg.find("<title>seeds/&lt;cut&gt; &amp; &quot;co&quot;.avu</title>"),
            std::string::npos);
  EXPECT_EQ(svg.find("<cut>"), std::string::npos);
}

TEST(TrendChartTest, BarsByStatusPerRun) {
  std::vector<ReportRun> runs(2);
  runs[0].run = {1, "2026-11-25T02:00:00Z", "2026-11-25T03:00:00Z", "v<1>"};
  runs[0].modes_first_seen = 3;
  runs[0].modes_seen = 3;
  runs[1].run = {2, "2026-11-26T02:00:00Z", "", "v2"};
  runs[1].modes_first_seen = 1;
  runs[1].modes_seen = 4;
  runs[1].regressed = 1;
  runs[1].fixed = 2;
  const std::string svg = trend_chart_svg(runs);
  EXPECT_EQ(count(svg, "<rect class=\"bar new\""), 2u);
  EXPECT_EQ(count(svg, "<rect class=\"bar regressed\""), 1u);
  EXPECT_EQ(count(svg, "<rect class=\"bar still-failing\""), 1u);  // 4 - 1 - 1 in run 2
  EXPECT_EQ(count(svg, "<rect class=\"bar fixed\""), 1u);
  EXPECT_NE(svg.find("<title>run 2: 2 still failing</title>"), std::string::npos);
  EXPECT_NE(svg.find(">2026-11-25 · v&lt;1&gt;</text>"), std::string::npos);
  EXPECT_NE(trend_chart_svg({}).find("no runs yet"), std::string::npos);
}

}  // namespace
}  // namespace scenfuzz
