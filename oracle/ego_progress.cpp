#include "oracle/ego_progress.hpp"

#include <cmath>

#include "lang/number_format.hpp"
#include "oracle/law_signals.hpp"

namespace scenfuzz {

namespace {

constexpr double kRedCode = 1, kYellowCode = 2;  // law_signals' trafficLightAhead.color codes

// The first sample of the last kStuckWindow seconds.
std::size_t window_start(const Trace& trace) {
  const double from = trace.time.back() - kStuckWindow;
  std::size_t first = trace.sample_count() - 1;
  while (first > 0 && trace.time[first - 1] >= from - 1e-9) --first;
  return first;
}

double path_length(const TraceActor& ego, std::size_t first, std::size_t last) {
  double length = 0;
  for (std::size_t i = first + 1; i <= last; ++i)
    length += std::hypot(ego.x[i] - ego.x[i - 1], ego.y[i] - ego.y[i - 1]);
  return length;
}

bool held_by_a_light(const Trace& trace, const ScenarioTemplate& scenario,
                     std::span<const double> parameters, const RoadMap& map, std::size_t first) {
  SpecTerm colour;
  colour.kind = TermKind::signal;
  colour.name = "trafficLightAhead.color";
  try {
    const SignalValues codes = law_signal(colour, trace, scenario, parameters, map);
    for (std::size_t i = first; i < codes.values.size(); ++i)
      if (codes.values[i] == kRedCode || codes.values[i] == kYellowCode) return true;
  } catch (const OracleError&) {
    // A light the trace has no colours for cannot hold the ego.
  }
  return false;
}

}  // namespace

EgoProgress ego_progress_at_end(const Trace& trace, const ScenarioTemplate& scenario,
                                std::span<const double> parameters, const RoadMap& map) {
  EgoProgress progress;
  if (trace.sample_count() == 0) return progress;
  const std::size_t first = window_start(trace);
  const std::size_t last = trace.sample_count() - 1;
  const double driven = path_length(trace.actors[kEgo], first, last);
  const double seconds = trace.time[last] - trace.time[first];
  progress.description = "drove " + format_number(std::round(driven * 10) / 10) +
                         " m in the last " + format_number(std::round(seconds * 100) / 100) + " s";
  if (driven >= kStuckDistance) return progress;
  if (held_by_a_light(trace, scenario, parameters, map, first)) {
    progress.description += ", held by a red light";
    return progress;
  }
  progress.stuck = true;
  progress.description += " with no red light ahead";
  return progress;
}

}  // namespace scenfuzz
