// The JUnit XML of a campaign run (junit_report.hpp), written with pugixml, which escapes text
// and attributes. The de-facto schema CI systems read: testsuites / testsuite (name, tests,
// failures, errors, skipped, time, timestamp) / properties, testcase (name, classname, time) /
// failure | error | skipped (message, type) with the details as text.
#include "fuzz/campaign/junit_report.hpp"

#include <map>
#include <pugixml.hpp>
#include <sstream>
#include <vector>

#include "fuzz/campaign/run_exit_status.hpp"

namespace scenfuzz {

namespace {

// Control characters other than tab and line breaks are not allowed in XML 1.0, even escaped; a
// plugin's message may hold them.
std::string xml_text(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') c = '?';
  return text;
}

void set(pugi::xml_node node, const char* name, const std::string& value) {
  node.append_attribute(name).set_value(xml_text(value).c_str());
}

struct Counts {
  std::size_t tests = 0, failures = 0, errors = 0, skipped = 0;
};

void set_counts(pugi::xml_node node, const Counts& counts) {
  set(node, "tests", std::to_string(counts.tests));
  set(node, "failures", std::to_string(counts.failures));
  set(node, "errors", std::to_string(counts.errors));
  set(node, "skipped", std::to_string(counts.skipped));
  set(node, "time", "0");  // the run is not timed per failure mode
}

std::string status_meaning(FailureModeStatus status) {
  switch (status) {
    case FailureModeStatus::new_mode: return "first found in this run";
    case FailureModeStatus::still_failing: return "still fails";
    case FailureModeStatus::fixed: return "no longer fails";
    case FailureModeStatus::flaky: return "fails with some perception seeds only";
    case FailureModeStatus::regressed: return "was fixed, and fails again";
  }
  return "";
}

std::string one_line_summary(const CampaignFailureMode& mode) {
  const FailureModeRecord& record = mode.record;
  return std::string(status_name(mode.status)) + ": spec " + record.spec +
         (record.responsibility.empty() ? "" : ", " + record.responsibility + " responsibility") +
         "; replay: " + record.replay_command;
}

// The details, a line each: what the CI page shows under the test case.
std::string details(const RunFailureMode& entry) {
  const FailureModeRecord& record = entry.mode.record;
  std::string text = "status: " + std::string(status_name(entry.mode.status)) + " (" +
                     status_meaning(entry.mode.status) + ")\n";
  text += "spec: " + record.spec + "\nfailure mode: " + record.signature + "\n";
  if (!record.responsibility.empty()) text += "responsibility: " + record.responsibility + "\n";
  text += "seed: " + entry.seed_path + "\nscenario: " + record.scenario_file + "\n";
  text += "first seen in run " + std::to_string(entry.mode.first_seen_run) + ", last seen in run " +
          std::to_string(entry.mode.last_seen_run) + "\n";
  if (entry.replay && entry.replay->error.empty())
    text += "replay: " + std::to_string(entry.replay->failing) + " of " +
            std::to_string(entry.replay->tried) + " perception seeds failed the same way\n";
  if (entry.replay && !entry.replay->error.empty())
    text += "replay error: " + entry.replay->error + "\n";
  return text + "replay command (from the campaign folder): " + record.replay_command + "\n";
}

// One <testcase>, counted into `counts`.
void add_case(pugi::xml_node suite, const RunSummary& summary, const RunFailureMode& entry,
              Counts& counts) {
  pugi::xml_node test = suite.append_child("testcase");
  set(test, "name", entry.mode.record.spec + ": " + entry.mode.record.signature);
  std::string classname = entry.seed_path;  // dots would split it into package and class
  for (char& c : classname)
    if (c == '.') c = '_';
  set(test, "classname", classname);
  set(test, "time", "0");
  ++counts.tests;
  const RunEvidence evidence = run_evidence(summary, entry);
  pugi::xml_node outcome;
  if (evidence == RunEvidence::replay_failed) {
    outcome = test.append_child("error");
    set(outcome, "message", "the replay failed: " + entry.replay->error);
    set(outcome, "type", "replay_error");
    ++counts.errors;
  } else if (evidence == RunEvidence::none) {
    outcome = test.append_child("skipped");
    set(outcome, "message", "neither replayed nor found in this run");
    ++counts.skipped;
  } else if (entry.mode.status != FailureModeStatus::fixed) {
    outcome = test.append_child("failure");
    set(outcome, "message", one_line_summary(entry.mode));
    set(outcome, "type", std::string(status_name(entry.mode.status)));
    ++counts.failures;
  } else {
    outcome = test.append_child("system-out");
  }
  outcome.append_child(pugi::node_pcdata).set_value(xml_text(details(entry)).c_str());
}

void add_properties(pugi::xml_node suite, const RunSummary& summary) {
  pugi::xml_node properties = suite.append_child("properties");
  const std::vector<std::pair<std::string, std::string>> values = {
      {"campaign", summary.campaign},
      {"run", std::to_string(summary.run.id)},
      {"ego_version", summary.run.ego_version},
      {"exit_status", run_exit_reason(summary)}};
  for (const auto& [name, value] : values) {
    pugi::xml_node property = properties.append_child("property");
    set(property, "name", name);
    set(property, "value", value);
  }
}

// "2026-11-27T02:00:00": JUnit's timestamps have no zone (the run's are UTC).
std::string junit_timestamp(std::string time) {
  if (!time.empty() && time.back() == 'Z') time.pop_back();
  return time;
}

}  // namespace

std::string junit_xml(const RunSummary& summary) {
  std::map<std::string, std::vector<const RunFailureMode*>> by_seed;  // sorted by seed path
  for (const RunFailureMode& entry : summary.failure_modes)
    by_seed[entry.seed_path].push_back(&entry);

  pugi::xml_document document;
  pugi::xml_node declaration = document.append_child(pugi::node_declaration);
  declaration.append_attribute("version").set_value("1.0");
  declaration.append_attribute("encoding").set_value("UTF-8");
  pugi::xml_node suites = document.append_child("testsuites");
  set(suites, "name",
      "scenfuzz campaign " + summary.campaign + ", run " + std::to_string(summary.run.id));
  Counts total;
  for (const auto& [seed, entries] : by_seed) {
    pugi::xml_node suite = suites.append_child("testsuite");
    set(suite, "name", seed);
    add_properties(suite, summary);  // before the test cases, as the schema orders them
    Counts counts;
    for (const RunFailureMode* entry : entries) add_case(suite, summary, *entry, counts);
    set_counts(suite, counts);
    set(suite, "timestamp", junit_timestamp(summary.run.started));
    total.tests += counts.tests;
    total.failures += counts.failures;
    total.errors += counts.errors;
    total.skipped += counts.skipped;
  }
  set_counts(suites, total);
  std::ostringstream text;
  document.save(text, "  ", pugi::format_default, pugi::encoding_utf8);
  return text.str();
}

}  // namespace scenfuzz
