// A concrete scenario's header names each search dimension by the value of what the user wrote and
// where its range's draw came from: a range inside an expression was printed
// "lead.init.speed = -1.97 m/s" (its draw) where the file says `lead_speed = 10 + range(-3, 3)`.
// The printers themselves write it, so that every user of them (findings, `scenfuzz run`, tmin,
// campaigns) shows the same header.
#include "lang/parameter_provenance.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "tests/lang/wmg_test_files.hpp"

namespace scenfuzz {
namespace {

const char* const kText = R"(// lead ahead
ego_init = ("east_0"->range(20, 40), , 12);
ego = AV(ego_init, ("east_0"->400), ("Lincoln2017MKZ", white));
lead_speed = 10 + range(-3, 3);
lead_init = ("east_0"->80, , lead_speed);
lead_stop = ("east_0"->150 + lead_speed * range(1.0, 2.0), , 0);
lead = Vehicle(lead_init, Waypoint(lead_stop), lead_stop, ("Sedan", red));
scenario = CreateScenario{load("straight"); ego; {lead}; {}; {};};
)";

struct Parsed {
  explicit Parsed(const std::string& text = kText) : file("base.avu", text) {}
  SourceFile file;
  avunit::ParseResult result = avunit::parse(file);
};

std::size_t index_of(const ScenarioTemplate& scenario, const std::string& name) {
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].name == name) return i;
  ADD_FAILURE() << "no dimension " << name;
  return 0;
}

// The header: the comment lines before the user's text.
std::string header_of(const std::string& printed, const std::string& first_line_of_body) {
  return printed.substr(0, printed.find(first_line_of_body));
}

TEST(ParameterProvenanceTest, ARangeInsideAnExpressionIsNamedByTheResultingValue) {
  const Parsed parsed;
  ASSERT_TRUE(parsed.result.ok());
  const ScenarioTemplate& scenario = parsed.result.scenario;
  ASSERT_EQ(scenario.parameters.size(), 3u);
  const std::vector<double> values = {30, -1.97, 1.5};
  const std::size_t speed = index_of(scenario, "lead.init.speed");
  const auto provenance = parameter_provenance(parsed.file, scenario, values, speed);
  ASSERT_TRUE(provenance.has_value());
  EXPECT_DOUBLE_EQ(provenance->value, 8.03);
  EXPECT_EQ(provenance->drawn, -1.97);
  EXPECT_EQ(provenance->range_text, "range(-3, 3)");
  EXPECT_EQ(provenance_text(parsed.file, scenario.parameters[speed], *provenance),
            "lead.init.speed = 8.03 m/s, where range(-3, 3) drew -1.97 (base.avu:4:19)");
  // A range that is the whole value is its draw: nothing to add.
  EXPECT_FALSE(parameter_provenance(parsed.file, scenario, values,
                                    index_of(scenario, "ego.init.position.s")));
}

TEST(ParameterProvenanceTest, TheAvunitConcreteHeaderShowsResultingValues) {
  const Parsed parsed;
  ASSERT_TRUE(parsed.result.ok());
  const std::vector<double> values = {30, -1.97, 1.5};
  const std::string printed = avunit::print_concrete(parsed.file, parsed.result.scenario, values);
  const std::string header = header_of(printed, "// lead ahead");
  EXPECT_EQ(header,
            "// concrete scenario of base.avu chosen by scenfuzz:\n"
            "//   ego.init.position.s = 30 m\n"
            "//   lead.init.speed = 8.03 m/s, where range(-3, 3) drew -1.97 (base.avu:4:19)\n"
            // 150 + 8.03 * 1.5
            "//   lead.waypoint[0].position.s = 162.045 m, where range(1.0, 2.0) drew 1.5 "
            "(base.avu:6:43)\n");
  // The scenario itself has the draws in place of the ranges, and reads back concrete.
  EXPECT_NE(printed.find("lead_speed = 10 + -1.97;"), std::string::npos) << printed;
  const avunit::ParseResult reparsed = avunit::parse(SourceFile("finding.avu", printed));
  ASSERT_TRUE(reparsed.ok()) << printed;
  EXPECT_TRUE(reparsed.scenario.parameters.empty());
}

TEST(ParameterProvenanceTest, ARangeWrittenOverSeveralLinesStaysInItsCommentLine) {
  std::string text = kText;
  const std::string range = "range(-3, 3)";
  text.replace(text.find(range), range.size(), "range(-3,\n                  3)");
  const Parsed parsed(text);
  ASSERT_TRUE(parsed.result.ok());
  const std::vector<double> values = {30, -1.97, 1.5};
  const std::string printed = avunit::print_concrete(parsed.file, parsed.result.scenario, values);
  EXPECT_NE(printed.find("//   lead.init.speed = 8.03 m/s, where range(-3, 3) drew -1.97 "
                         "(base.avu:4:19)\n"),
            std::string::npos)
      << printed;
  // Every header line is a comment, so the finding reads back.
  const std::string header = header_of(printed, "// lead ahead");
  EXPECT_EQ(std::count(header.begin(), header.end(), '\n'), 4) << header;
  const avunit::ParseResult reparsed = avunit::parse(SourceFile("finding.avu", printed));
  EXPECT_TRUE(reparsed.ok()) << printed;
}

// WMG SDL has no arithmetic: a range `a to b` stands alone where a number may be, so the value of
// what the user wrote is the draw itself, in the file's unit. The translator does wrap ranges in
// conversions (oktas / 8 for the cloudiness); the header must not name those.
TEST(ParameterProvenanceTest, WmgHeaderLinesNameTheDrawInTheFilesUnit) {
  wmg::test::Parts parts;
  parts.scenery = wmg::test::scenery_with_roads(wmg::test::road());
  parts.environment =
      "ENVIRONMENT ELEMENTS:\nDO: [E]\nWind [10 to 50]\nCloudiness [2 to 6]\n"
      "Rainfall [Light Rain: 0]\nTime of the day [Any]\n"
      "Illumination [Day] with [Sun] as light source\n";
  const SourceFile file("w.sdl", parts.text());
  const wmg::ParseResult parsed = wmg::parse(file);
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics.all().front().message;
  const ScenarioTemplate& scenario = parsed.scenario;
  ASSERT_EQ(scenario.parameters.size(), 2u);
  std::vector<double> values(2);
  values[index_of(scenario, "environment.wind")] = 30;
  values[index_of(scenario, "environment.cloudiness")] = 4;
  // The IR's slot is an expression around the range (what the oracle and simulator read) ...
  EXPECT_TRUE(
      parameter_provenance(file, scenario, values, index_of(scenario, "environment.cloudiness")));
  // ... but the header names the value the file now holds.
  const std::string printed = wmg::print_concrete(file, scenario, values);
  EXPECT_EQ(header_of(printed, "VERSION:"),
            "# concrete scenario of w.sdl chosen by scenfuzz:\n"
            "#   environment.wind = 30 km/h\n"
            "#   environment.cloudiness = 4 oktas\n")
      << printed;
  EXPECT_NE(printed.find("Wind [30]\nCloudiness [4]\n"), std::string::npos) << printed;
}

}  // namespace
}  // namespace scenfuzz
