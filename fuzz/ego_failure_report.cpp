// `scenfuzz run`'s report of a failed ego plugin, in words and as JSON.
#include "fuzz/ego_failure_report.hpp"

#include <cmath>

#include "lang/number_format.hpp"

namespace scenfuzz {

std::optional<EgoFailureReport> ego_failure_report(const Trace& trace) {
  if (trace.end != EndReason::ego_failure && !trace.ego_failure) return std::nullopt;
  EgoFailureReport report;
  report.failure = trace.ego_failure;
  for (const TraceEvent& event : trace.events)
    if (event.kind == TraceEventKind::ego_failure) {
      report.message = event.message;
      report.time = event.time;
    }
  if (report.failure) report.time = report.failure->time;
  if (report.message.empty() && report.failure) report.message = report.failure->reason;
  return report;
}

bool ego_failed_to_start(const Trace& trace, const EgoFailureReport& report) {
  if (report.failure)
    return report.failure->step == 0 && report.failure->kind == EgoFailureKind::error;
  return trace.sample_count() == 0;
}

std::string describe_ego_failure(const EgoFailureReport& report) {
  const std::string time = "t = " + format_number(std::round(report.time * 1000) / 1000) + " s";
  if (!report.failure) return "ego failure at " + time + ": " + report.message;
  const EgoFailure& failure = *report.failure;
  std::string text = "ego failure: " + std::string(ego_failure_kind_name(failure.kind));
  if (!failure.signal.empty()) text += " (" + failure.signal + ")";
  text += failure.step == 0 ? " while starting" : " at step " + std::to_string(failure.step);
  return text + ", " + time + ": " + failure.reason;
}

nlohmann::json ego_failure_json(const EgoFailureReport& report) {
  nlohmann::json json = {{"kind", nullptr},     {"reason", report.message},
                         {"signal", nullptr},   {"step", nullptr},
                         {"time", report.time}, {"last_observation", nullptr}};
  if (!report.failure) return json;
  const EgoFailure& failure = *report.failure;
  json["kind"] = std::string(ego_failure_kind_name(failure.kind));
  json["reason"] = failure.reason;
  if (!failure.signal.empty()) json["signal"] = failure.signal;
  json["step"] = failure.step;
  if (!failure.last_observation.empty()) {
    // The observation is JSON already; kept as text should it not parse.
    nlohmann::json observation = nlohmann::json::parse(failure.last_observation, nullptr, false);
    json["last_observation"] =
        observation.is_discarded() ? nlohmann::json(failure.last_observation) : observation;
  }
  return json;
}

}  // namespace scenfuzz
