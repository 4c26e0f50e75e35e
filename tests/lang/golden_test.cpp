// Golden tests, one input per grammar rule (tests/lang/data/golden/*.avu, *.scenest): the
// template each parses to, shown as its canonical AVUnit and its parameter table, must equal the
// reviewed `.golden` file beside it. Regenerate after a deliberate change with
// SCENFUZZ_UPDATE_GOLDEN=1 and review the diff.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "lang/avunit/avunit.hpp"
#include "lang/number_format.hpp"
#include "tests/lang/test_files.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

std::string golden_text(const ScenarioTemplate& scenario) {
  std::string text = avunit::print(scenario);
  text += "// parameters:\n";
  for (const Parameter& parameter : scenario.parameters)
    text += "//   " + parameter.name + " " + std::string(kind_name(parameter.kind)) + " [" +
            format_number(parameter.lower) + ", " + format_number(parameter.upper) + "] " +
            parameter.unit + " at " + std::to_string(parameter.location.line) + ":" +
            std::to_string(parameter.location.column) + "\n";
  for (const Spec& spec : scenario.specs)
    text += "// spec " + spec.name + " on " + spec.trace + "\n";
  return text;
}

// Compares the golden text of `input` with `golden` (or rewrites it when updating).
void expect_golden(const std::filesystem::path& input, const std::filesystem::path& golden) {
  SCOPED_TRACE(input.string());
  SourceFile file = test::load(input);
  avunit::ParseResult parsed = avunit::parse(file);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);
  EXPECT_TRUE(parsed.diagnostics.all().empty()) << format_diagnostics(file, parsed.diagnostics);
  std::string actual = golden_text(parsed.scenario);
  if (std::getenv("SCENFUZZ_UPDATE_GOLDEN") != nullptr) {
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << "run with SCENFUZZ_UPDATE_GOLDEN=1";
  EXPECT_EQ(actual, test::load(golden).text());

  avunit::ParseResult reparsed =
      avunit::parse(SourceFile(input.string(), avunit::print(parsed.scenario)));
  ASSERT_TRUE(reparsed.ok());
  EXPECT_EQ(parsed.scenario, reparsed.scenario);
}

TEST(Golden, EachGrammarRuleParsesToItsReviewedTemplate) {
  auto inputs = test::files_in(test::lang_data_dir() / "golden", {".avu", ".scenest"});
  ASSERT_GE(inputs.size(), 20u);
  for (const auto& input : inputs) {
    std::filesystem::path golden = input;
    golden.replace_extension(input.extension().string() + ".golden");
    expect_golden(input, golden);
  }
}

// The real files written by others for other tools (their goldens live here, the files do not).
TEST(Golden, EverySharedExampleParsesToItsReviewedTemplate) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  std::vector<std::filesystem::path> inputs;
  for (const char* language : {"avunit", "scenest"})
    for (const auto& input :
         test::files_in(test::shared_dir() / "examples" / language, {".avu", ".scenest"}))
      inputs.push_back(input);
  ASSERT_EQ(inputs.size(), 7u);
  for (const auto& input : inputs)
    expect_golden(input,
                  test::lang_data_dir() / "examples" / (input.filename().string() + ".golden"));
}

}  // namespace
}  // namespace scenfuzz
