// Cross-check against RTAMT: the 81 LawBreaker sub-violation formulas over the signals LawBreaker
// derived from its example trace (../shared/reference/lawbreaker-golden-example.json), evaluated
// by our engine and compared with the robustness LawBreaker's RTAMT computed. The formulas are in
// RTAMT's syntax; a few word substitutions make them AVUnit. All agree but one: RTAMT 0.2.7 leaves
// the last sample out of bounded windows (reference section 4.3), and in #36 the decisive window
// is the one at the last sample, which holds that sample alone for us (speed 3.63 km/h: -3.13)
// and is empty of it for RTAMT, whose value comes from the sample before (4.46: -3.96).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>

#include "../support/shared_dir.hpp"
#include "lang/avunit/avunit.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {
namespace {

// eventually(...) -> F(...), always[0,2] -> G[0,2], and/or/not -> & | ~.
std::string avunit_text(const std::string& rtamt) {
  std::string text = std::regex_replace(rtamt, std::regex(R"(\beventually\b)"), "F");
  text = std::regex_replace(text, std::regex(R"(\balways\b)"), "G");
  text = std::regex_replace(text, std::regex(R"(\band\b)"), " & ");
  text = std::regex_replace(text, std::regex(R"(\bor\b)"), " | ");
  return std::regex_replace(text, std::regex(R"(\bnot\b)"), "~");
}

TEST(LawBreakerGoldenTest, SubViolationRobustnessMatchesRtamt) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  std::ifstream in(test::shared_dir() / "reference" / "lawbreaker-golden-example.json");
  ASSERT_TRUE(in);
  const nlohmann::json golden = nlohmann::json::parse(in);
  const std::vector<double> time = golden["time"].get<std::vector<double>>();
  std::map<std::string, std::vector<double>> columns;
  for (const auto& [name, values] : golden["signals"].items())
    columns[name] = values.get<std::vector<double>>();
  SignalSource source;
  source.time = time;
  source.leaf = [&](const SpecTerm& term) {
    auto found = columns.find(term.name);
    if (found == columns.end()) throw OracleError(term.location, "no signal " + term.name);
    return SignalValues{found->second, false};
  };

  std::size_t agreeing = 0;
  std::vector<int> differing;
  for (const nlohmann::json& sub : golden["sub_violations"]) {
    const std::string text = avunit_text(sub["rtamt"].get<std::string>());
    SCOPED_TRACE(text);
    const avunit::FormulaParseResult parsed = avunit::parse_formula(SourceFile("golden", text));
    ASSERT_TRUE(parsed.formula) << format_diagnostics(SourceFile("golden", text),
                                                      parsed.diagnostics);
    const double ours = robustness_signal(*parsed.formula, source)[0];
    const double theirs = sub["robustness"].get<double>();
    // RTAMT computes in single precision here.
    if (std::abs(ours - theirs) <= 1e-4 * std::max(1.0, std::abs(theirs)))
      ++agreeing;
    else
      differing.push_back(sub["index"].get<int>());
  }
  EXPECT_EQ(agreeing, 80u);
  EXPECT_EQ(differing, std::vector<int>{36});
}

}  // namespace
}  // namespace scenfuzz
