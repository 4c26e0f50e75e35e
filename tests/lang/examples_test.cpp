// Every bundled corpus file and every real example in ../shared/examples parses without errors,
// prints back to an equal template, and prints as a concrete scenario that is fully fixed.
#include <gtest/gtest.h>

#include <algorithm>

#include "lang/avunit/avunit.hpp"
#include "tests/lang/test_files.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

using test::files_in;
using test::load;

void expect_parses_and_round_trips(const std::filesystem::path& path) {
  SCOPED_TRACE(path.string());
  SourceFile file = load(path);
  avunit::ParseResult parsed = avunit::parse(file);
  ASSERT_TRUE(parsed.ok()) << format_diagnostics(file, parsed.diagnostics);

  std::string printed = avunit::print(parsed.scenario);
  // Same extension: .scenest and .avu read into templates of different source languages.
  std::string printed_path = path.string() + ".printed" + path.extension().string();
  avunit::ParseResult reparsed = avunit::parse(SourceFile(printed_path, printed));
  ASSERT_TRUE(reparsed.ok()) << printed << "\n"
                             << format_diagnostics(SourceFile("printed", printed),
                                                   reparsed.diagnostics);
  EXPECT_EQ(parsed.scenario, reparsed.scenario) << printed;
  EXPECT_EQ(avunit::print(reparsed.scenario), printed);

  // The midpoint of every range, spliced into the user's own text, leaves a concrete scenario.
  std::vector<double> midpoint;
  for (const Parameter& parameter : parsed.scenario.parameters)
    midpoint.push_back((parameter.lower + parameter.upper) / 2);
  std::string concrete = avunit::print_concrete(file, parsed.scenario, midpoint);
  avunit::ParseResult fixed = avunit::parse(SourceFile(path.string(), concrete));
  ASSERT_TRUE(fixed.ok()) << concrete;
  EXPECT_TRUE(fixed.scenario.parameters.empty()) << concrete;
  EXPECT_EQ(fixed.scenario.vehicles.size(), parsed.scenario.vehicles.size());
  EXPECT_EQ(fixed.scenario.specs.size(), parsed.scenario.specs.size());
}

TEST(Examples, BundledCorpusFilesParseAndRoundTrip) {
  auto files = files_in(test::corpus_dir(), {".avu"});
  ASSERT_GE(files.size(), 12u) << "the corpus lives in " << test::corpus_dir();
  for (const auto& path : files) expect_parses_and_round_trips(path);
}

TEST(Examples, SharedAvunitExamplesParseAndRoundTrip) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  auto files = files_in(test::shared_dir() / "examples" / "avunit", {".avu"});
  ASSERT_EQ(files.size(), 3u);
  for (const auto& path : files) expect_parses_and_round_trips(path);
}

TEST(Examples, SharedScenestExamplesParseAndRoundTrip) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  auto files = files_in(test::shared_dir() / "examples" / "scenest", {".scenest"});
  ASSERT_EQ(files.size(), 4u);
  for (const auto& path : files) expect_parses_and_round_trips(path);
}

TEST(Examples, EveryCorpusFileHasRangesAndASpec) {
  for (const auto& path : files_in(test::corpus_dir(), {".avu"})) {
    SCOPED_TRACE(path.string());
    avunit::ParseResult parsed = avunit::parse(load(path));
    ASSERT_TRUE(parsed.ok());
    EXPECT_TRUE(parsed.scenario.has_scenario);
    EXPECT_FALSE(parsed.scenario.parameters.empty());
    EXPECT_FALSE(parsed.scenario.specs.empty());
    // No warnings either: every range of a seed scenario is a search dimension.
    EXPECT_TRUE(parsed.diagnostics.all().empty());
  }
}

}  // namespace
}  // namespace scenfuzz
