// A driver test in words and JSON (driver_test_report.hpp).
#include "fuzz/driver_test_report.hpp"

#include <cmath>

#include "fuzz/collision_report.hpp"
#include "fuzz/ego_failure_report.hpp"
#include "fuzz/report_format.hpp"
#include "lang/number_format.hpp"
#include "physics/collision/body_side.hpp"

namespace scenfuzz {

namespace {

std::string seconds(double time) { return format_number(std::round(time * 100) / 100) + " s"; }

const Collision& first_collision(const DriverTest& test) {
  return test.run.trace->collisions[*test.collision];
}

std::string other_name(const DriverTest& test) {
  const Collision& c = first_collision(test);
  return test.run.trace->actors[c.first == kEgo ? c.second : c.first].name;
}

bool reached_target(const DriverTest& test) {
  return test.run.trace && test.run.trace->end == EndReason::target_reached;
}

// What happened, after "<driver> in <vehicle>'s place".
std::string outcome_words(const DriverTest& test) {
  const Trace& trace = *test.run.trace;
  switch (test.verdict) {
    case DriverVerdict::avoided:
      return reached_target(test) ? "avoided the accident and drove on past it"
                                  : "no collision, but it did not get past the scene in " +
                                        seconds(trace.time.back()) +
                                        ": it may have avoided the accident by not "
                                        "driving";
    case DriverVerdict::unavoidable:
      return "hit by " + other_name(test) + " at " + seconds(first_collision(test).time) + ", " +
             other_name(test) + "'s fault, and braking could not have avoided it";
    case DriverVerdict::avoidable:
      return "hit by " + other_name(test) + " at " + seconds(first_collision(test).time) + ", " +
             other_name(test) + "'s fault, but braking in time would have avoided it";
    case DriverVerdict::caused:
      return "collided with " + other_name(test) + " at " + seconds(first_collision(test).time) +
             ", " +
             responsibility_words(
                 std::string(responsibility_name(test.responsibility->responsibility)));
    case DriverVerdict::ego_failure: return "the driver failed while driving";
  }
  return "";
}

}  // namespace

std::string driver_test_headline(const DriverTest& test, const DriverSeat& seat) {
  return std::string(is_driver_finding(test.verdict) ? "finding: " : "") + seat.driver + " in " +
         seat.vehicle + "'s place: " + outcome_words(test);
}

std::vector<std::string> driver_test_lines(const DriverTest& test, const DriverSeat& seat) {
  std::vector<std::string> lines = {"driver test: " + driver_test_headline(test, seat)};
  const Trace& trace = *test.run.trace;
  if (test.verdict == DriverVerdict::ego_failure)
    if (const std::optional<EgoFailureReport> failure = ego_failure_report(trace))
      lines.push_back("  " + describe_ego_failure(*failure));
  if (test.collision) lines.push_back("  " + describe_collision(trace, first_collision(test)));
  if (test.responsibility) {
    // Two lines, already indented.
    std::string text = describe_responsibility(trace, *test.responsibility);
    const std::size_t cut = text.find('\n');
    lines.push_back(text.substr(0, cut));
    if (cut != std::string::npos) lines.push_back(text.substr(cut + 1));
  }
  if (test.avoidability) lines.push_back("  avoidability: " + test.avoidability->reason);
  return lines;
}

nlohmann::json driver_test_json(const DriverTest& test, const DriverSeat& seat,
                                const std::vector<std::string>& written) {
  nlohmann::json json = {{"driver", seat.driver},
                         {"ego", seat.vehicle},
                         {"verdict", driver_verdict_name(test.verdict)},
                         {"finding", is_driver_finding(test.verdict)},
                         {"reached_target", reached_target(test)},
                         {"collision", nullptr},
                         {"responsibility", nullptr},
                         {"avoidability", nullptr},
                         {"written", written}};
  if (test.collision) {
    const Collision& c = first_collision(test);
    const bool ego_first = c.first == kEgo;
    json["collision"] = {{"time", c.time},
                         {"other", other_name(test)},
                         {"point", {c.point.x, c.point.y}},
                         {"ego_side", body_side_name(ego_first ? c.first_side : c.second_side)},
                         {"other_side", body_side_name(ego_first ? c.second_side : c.first_side)}};
  }
  if (test.responsibility)
    json["responsibility"] = {{"blame", responsibility_name(test.responsibility->responsibility)},
                              {"reason", test.responsibility->reason},
                              {"triage", responsibility_json(*test.responsibility)}};
  if (test.avoidability) {
    const Avoidability& a = *test.avoidability;
    json["avoidability"] = {{"avoidable", a.avoidable},   {"conflict_time", a.conflict_time},
                            {"brake_time", a.brake_time}, {"clearance", a.clearance},
                            {"stop_short", a.stop_short}, {"reason", a.reason}};
  }
  if (test.verdict == DriverVerdict::ego_failure)
    if (const std::optional<EgoFailureReport> failure = ego_failure_report(*test.run.trace))
      json["ego_failure"] = ego_failure_json(*failure);
  return json;
}

}  // namespace scenfuzz
