// The JUnit XML of a campaign run, read back with pugixml: one testsuite per seed with the
// counts CI systems read, one testcase per failure mode; new, still failing, flaky and regressed
// modes are failures naming status, spec, responsibility and replay command; fixed ones pass; a
// failed replay is an error and a mode the run learnt nothing about is skipped; text is escaped.
#include "fuzz/campaign/junit_report.hpp"

#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <string>

#include "tests/campaign/sample_run.hpp"

namespace scenfuzz::test {
namespace {

const std::string kCutIn = "corpora/avunit/cut_in_straight.avu";
const std::string kSdl = "extra/overtake.sdl";

// One mode per way a run leaves one, over two seeds.
RunSummary every_kind_of_mode() {
  RunSummary summary = empty_run();
  auto replayed = [](RunFailureMode entry, ReplayOutcome outcome) {
    entry.replay = std::move(outcome);
    return entry;
  };
  summary.failure_modes = {
      sample_mode(1, kCutIn, FailureModeStatus::new_mode, 3, 3),
      replayed(sample_mode(2, kCutIn, FailureModeStatus::still_failing, 1, 2), {3, 3, ""}),
      replayed(sample_mode(3, kCutIn, FailureModeStatus::fixed, 1, 2), {3, 0, ""}),
      replayed(sample_mode(4, kSdl, FailureModeStatus::flaky, 1, 2), {3, 2, ""}),
      replayed(sample_mode(5, kSdl, FailureModeStatus::regressed, 1, 1), {3, 3, ""}),
      replayed(sample_mode(6, kSdl, FailureModeStatus::still_failing, 2, 2),
               {0, 0, "modes/16.avu:3:9: error: lane 'x' is not in map 'straight'"}),
      sample_mode(7, kSdl, FailureModeStatus::fixed, 1, 1)};
  return summary;
}

pugi::xml_document parsed(const std::string& xml) {
  pugi::xml_document document;
  const pugi::xml_parse_result result = document.load_string(xml.c_str());
  EXPECT_TRUE(result) << result.description() << "\n" << xml;
  return document;
}

pugi::xml_node test_case(const pugi::xml_document& document, std::int64_t id) {
  const std::string suffix = "#" + std::to_string(id);
  for (pugi::xml_node suite : document.child("testsuites").children("testsuite"))
    for (pugi::xml_node test : suite.children("testcase")) {
      const std::string name = test.attribute("name").value();
      if (name.size() >= suffix.size() && name.ends_with(suffix)) return test;
    }
  return {};
}

TEST(JunitReport, OneSuitePerSeedWithTheCountsCiSystemsRead) {
  const std::string xml = junit_xml(every_kind_of_mode());
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0), 0u) << xml;
  const pugi::xml_document document = parsed(xml);
  const pugi::xml_node suites = document.child("testsuites");
  ASSERT_TRUE(suites);
  EXPECT_EQ(std::string(suites.attribute("name").value()), "scenfuzz campaign nightly, run 3");
  EXPECT_EQ(suites.attribute("tests").as_int(), 7);
  EXPECT_EQ(suites.attribute("failures").as_int(), 4);
  EXPECT_EQ(suites.attribute("errors").as_int(), 1);
  EXPECT_EQ(suites.attribute("skipped").as_int(), 1);

  std::vector<std::string> names;
  for (pugi::xml_node suite : suites.children("testsuite"))
    names.push_back(suite.attribute("name").value());
  EXPECT_EQ(names, (std::vector<std::string>{kCutIn, kSdl}));
  const pugi::xml_node cut_in = suites.find_child_by_attribute("testsuite", "name", kCutIn.c_str());
  EXPECT_EQ(cut_in.attribute("tests").as_int(), 3);
  EXPECT_EQ(cut_in.attribute("failures").as_int(), 2);
  EXPECT_EQ(cut_in.attribute("errors").as_int(), 0);
  EXPECT_EQ(cut_in.attribute("skipped").as_int(), 0);
  EXPECT_EQ(std::string(cut_in.attribute("timestamp").value()), "2026-11-27T02:00:00");
  EXPECT_EQ(std::string(cut_in.first_child().name()), "properties");
  const pugi::xml_node ego =
      cut_in.child("properties").find_child_by_attribute("property", "name", "ego_version");
  EXPECT_EQ(std::string(ego.attribute("value").value()), "3f2c9e1");
  const pugi::xml_node sdl = suites.find_child_by_attribute("testsuite", "name", kSdl.c_str());
  EXPECT_EQ(sdl.attribute("tests").as_int(), 4);
  EXPECT_EQ(sdl.attribute("failures").as_int(), 2);
  EXPECT_EQ(sdl.attribute("errors").as_int(), 1);
  EXPECT_EQ(sdl.attribute("skipped").as_int(), 1);
}

TEST(JunitReport, FailingModesAreFailuresNamingStatusSpecResponsibilityAndReplay) {
  const pugi::xml_document document = parsed(junit_xml(every_kind_of_mode()));
  const std::vector<std::pair<std::int64_t, std::string>> failing = {
      {1, "new"}, {2, "still_failing"}, {4, "flaky"}, {5, "regressed"}};
  for (const auto& [id, status] : failing) {
    const pugi::xml_node test = test_case(document, id);
    ASSERT_TRUE(test) << id;
    const pugi::xml_node failure = test.child("failure");
    ASSERT_TRUE(failure) << id;
    const std::string message = failure.attribute("message").value();
    EXPECT_EQ(std::string(failure.attribute("type").value()), status);
    EXPECT_EQ(message.rfind(status + ": spec no_collision, ego responsibility; replay: scenfuzz "
                                     "run --map-path maps modes/",
                            0),
              0u)
        << message;
    const std::string body = failure.text().get();
    EXPECT_NE(body.find("status: " + status), std::string::npos) << body;
    EXPECT_NE(body.find("failure mode: collision | car cutter"), std::string::npos) << body;
    EXPECT_NE(body.find("replay command (from the campaign folder): scenfuzz run"),
              std::string::npos)
        << body;
  }
  EXPECT_NE(std::string(test_case(document, 4).child("failure").text().get())
                .find("replay: 2 of 3 perception seeds failed the same way"),
            std::string::npos);
  const pugi::xml_node first = test_case(document, 1);
  EXPECT_EQ(std::string(first.attribute("classname").value()),
            "corpora/avunit/cut_in_straight_avu");
  EXPECT_EQ(std::string(first.attribute("name").value()),
            "no_collision: collision | car cutter | ego | cruising | straight | rear-front #1");
  EXPECT_TRUE(first.attribute("time"));
}

TEST(JunitReport, FixedPassesAFailedReplayIsAnErrorAndNoEvidenceIsSkipped) {
  const pugi::xml_document document = parsed(junit_xml(every_kind_of_mode()));
  const pugi::xml_node fixed = test_case(document, 3);
  EXPECT_FALSE(fixed.child("failure"));
  EXPECT_FALSE(fixed.child("error"));
  EXPECT_FALSE(fixed.child("skipped"));
  EXPECT_NE(std::string(fixed.child("system-out").text().get()).find("status: fixed"),
            std::string::npos);
  const pugi::xml_node error = test_case(document, 6).child("error");
  ASSERT_TRUE(error);
  EXPECT_EQ(std::string(error.attribute("type").value()), "replay_error");
  EXPECT_EQ(std::string(error.attribute("message").value()),
            "the replay failed: modes/16.avu:3:9: error: lane 'x' is not in map 'straight'");
  EXPECT_FALSE(test_case(document, 6).child("failure"));
  EXPECT_TRUE(test_case(document, 7).child("skipped"));
}

TEST(JunitReport, MarkupAndControlCharactersInTextStayWellFormed) {
  RunSummary summary = empty_run();
  summary.campaign = "a <b> & \"c\"";
  RunFailureMode mode = sample_mode(1, "x&y<z>.avu", FailureModeStatus::new_mode, 3, 3);
  mode.mode.record.signature = "dis(a, b) < 2 & \"q\" \x01 #1";
  summary.failure_modes = {mode};
  const pugi::xml_document document = parsed(junit_xml(summary));
  const pugi::xml_node suites = document.child("testsuites");
  EXPECT_EQ(std::string(suites.attribute("name").value()),
            "scenfuzz campaign a <b> & \"c\", run 3");
  EXPECT_EQ(std::string(suites.child("testsuite").attribute("name").value()), "x&y<z>.avu");
  EXPECT_EQ(std::string(test_case(document, 1).attribute("name").value()),
            "no_collision: dis(a, b) < 2 & \"q\" ? #1");
}

TEST(JunitReport, ARunWithoutFailureModesIsAnEmptyReport) {
  const pugi::xml_document document = parsed(junit_xml(empty_run()));
  const pugi::xml_node suites = document.child("testsuites");
  ASSERT_TRUE(suites);
  EXPECT_EQ(suites.attribute("tests").as_int(), 0);
  EXPECT_EQ(suites.attribute("failures").as_int(), 0);
  EXPECT_FALSE(suites.child("testsuite"));
}

}  // namespace
}  // namespace scenfuzz::test
