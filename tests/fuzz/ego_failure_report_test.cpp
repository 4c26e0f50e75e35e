// Tests of `scenfuzz run`'s report of a failed ego plugin (fuzz/ego_failure_report.hpp), on traces
// made by hand: with the failure the simulation records, and with only the ego_failure event.
#include "fuzz/ego_failure_report.hpp"

#include <gtest/gtest.h>

namespace scenfuzz {
namespace {

Trace failed_trace(const std::string& message, double time) {
  Trace trace;
  trace.time = {0, 0.05, 0.1};
  trace.end = EndReason::ego_failure;
  trace.events.push_back({TraceEventKind::ego_failure, time, -1, message});
  return trace;
}

TEST(EgoFailureReport, NoneWhenTheEgoDidNotFail) {
  Trace trace;
  trace.time = {0, 0.05};
  EXPECT_FALSE(ego_failure_report(trace).has_value());
}

TEST(EgoFailureReport, FromTheRecordedFailure) {
  Trace trace = failed_trace("ego plugin 'x.so' crashed (SIGSEGV) at step 3 (t = 0.1 s)", 0.1);
  trace.ego_failure = EgoFailure{EgoFailureKind::crash,
                                 "ego plugin 'x.so' crashed (SIGSEGV) at step 3 (t = 0.1 s)",
                                 "SIGSEGV",
                                 3,
                                 0.1,
                                 R"({"speed": 4})"};
  const std::optional<EgoFailureReport> report = ego_failure_report(trace);
  ASSERT_TRUE(report.has_value());
  EXPECT_FALSE(ego_failed_to_start(trace, *report));
  EXPECT_EQ(describe_ego_failure(*report),
            "ego failure: ego_crash (SIGSEGV) at step 3, t = 0.1 s: ego plugin 'x.so' crashed "
            "(SIGSEGV) at step 3 (t = 0.1 s)");
  const nlohmann::json json = ego_failure_json(*report);
  EXPECT_EQ(json.at("kind"), "ego_crash");
  EXPECT_EQ(json.at("signal"), "SIGSEGV");
  EXPECT_EQ(json.at("step"), 3);
  EXPECT_EQ(json.at("time"), 0.1);
  EXPECT_EQ(json.at("last_observation"), nlohmann::json({{"speed", 4}}));
}

TEST(EgoFailureReport, AHangHasNoSignal) {
  Trace trace = failed_trace("did not answer", 0);
  trace.ego_failure = EgoFailure{EgoFailureKind::hang, "did not answer within 2 s", "", 1, 0, ""};
  const EgoFailureReport report = *ego_failure_report(trace);
  EXPECT_EQ(describe_ego_failure(report),
            "ego failure: ego_hang at step 1, t = 0 s: did not answer within 2 s");
  EXPECT_TRUE(ego_failure_json(report).at("signal").is_null());
  EXPECT_TRUE(ego_failure_json(report).at("last_observation").is_null());
}

TEST(EgoFailureReport, FromTheEventAloneWhenTheFailureIsNotRecorded) {
  const Trace trace = failed_trace("ego plugin 'x.so' crashed (SIGSEGV) at step 3", 0.1);
  const EgoFailureReport report = *ego_failure_report(trace);
  EXPECT_FALSE(ego_failed_to_start(trace, report));
  EXPECT_EQ(describe_ego_failure(report),
            "ego failure at t = 0.1 s: ego plugin 'x.so' crashed (SIGSEGV) at step 3");
  const nlohmann::json json = ego_failure_json(report);
  EXPECT_TRUE(json.at("kind").is_null());
  EXPECT_EQ(json.at("reason"), "ego plugin 'x.so' crashed (SIGSEGV) at step 3");
  EXPECT_EQ(json.at("time"), 0.1);
}

// A plugin that cannot be loaded or created is a bad --ego-plugin; one that crashes while
// starting is the ego under test failing.
TEST(EgoFailureReport, FailingToStart) {
  Trace not_loaded = failed_trace("cannot load 'x.so'", 0);
  not_loaded.time.clear();
  EXPECT_TRUE(ego_failed_to_start(not_loaded, *ego_failure_report(not_loaded)));
  not_loaded.ego_failure = EgoFailure{EgoFailureKind::error, "cannot load 'x.so'", "", 0, 0, ""};
  const EgoFailureReport report = *ego_failure_report(not_loaded);
  EXPECT_TRUE(ego_failed_to_start(not_loaded, report));
  EXPECT_EQ(describe_ego_failure(report),
            "ego failure: ego_error while starting, t = 0 s: cannot "
            "load 'x.so'");

  Trace crashed_in_create = not_loaded;
  crashed_in_create.ego_failure->kind = EgoFailureKind::crash;
  EXPECT_FALSE(ego_failed_to_start(crashed_in_create, *ego_failure_report(crashed_in_create)));
}

}  // namespace
}  // namespace scenfuzz
