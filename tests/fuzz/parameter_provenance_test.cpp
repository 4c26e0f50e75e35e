// A finding names each search dimension by the value of what the user wrote and where its range's
// draw came from: a range inside an expression printed "lead.init.speed = -1.97 m/s" (its draw)
// where the file says `lead_speed = 10 + range(-3, 3)`.
#include "fuzz/parameter_provenance.hpp"

#include <gtest/gtest.h>

#include "lang/avunit/avunit.hpp"

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
  SourceFile file{"base.avu", kText};
  avunit::ParseResult result = avunit::parse(file);
};

std::size_t index_of(const ScenarioTemplate& scenario, const std::string& name) {
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    if (scenario.parameters[i].name == name) return i;
  ADD_FAILURE() << "no dimension " << name;
  return 0;
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

TEST(ParameterProvenanceTest, TheFindingsHeaderShowsResultingValuesAndKeepsTheRest) {
  const Parsed parsed;
  ASSERT_TRUE(parsed.result.ok());
  const std::vector<double> values = {30, -1.97, 1.5};
  const std::string printed = avunit::print_concrete(parsed.file, parsed.result.scenario, values);
  ASSERT_NE(printed.find("//   lead.init.speed = -1.97 m/s\n"), std::string::npos) << printed;
  const std::string shown =
      with_parameter_provenance(printed, parsed.file, parsed.result.scenario, values);
  EXPECT_EQ(shown.find("= -1.97 m/s"), std::string::npos) << shown;
  EXPECT_NE(shown.find("//   ego.init.position.s = 30 m\n"), std::string::npos) << shown;
  EXPECT_NE(shown.find("//   lead.init.speed = 8.03 m/s, where range(-3, 3) drew -1.97 "
                       "(base.avu:4:19)\n"),
            std::string::npos)
      << shown;
  // 150 + 8.03 * 1.5
  EXPECT_NE(shown.find("//   lead.waypoint[0].position.s = 162.045 m, where range(1.0, 2.0) drew "
                       "1.5 (base.avu:6:43)\n"),
            std::string::npos)
      << shown;
  // The scenario itself is untouched: only the header changed.
  EXPECT_EQ(shown.substr(shown.find("// lead ahead")),
            printed.substr(printed.find("// lead ahead")));
}

}  // namespace
}  // namespace scenfuzz
