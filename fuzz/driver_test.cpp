// A driver tested on a reconstruction (driver_test.hpp).
#include "fuzz/driver_test.hpp"

#include "fuzz/ego_failure_report.hpp"
#include "lang/demand.hpp"

namespace scenfuzz {

namespace {

// `scenfuzz run`'s default seed: the test is the run a user gets from the written file.
constexpr std::uint64_t kReplaySeed = 0;

std::optional<std::size_t> first_ego_collision(const Trace& trace) {
  for (std::size_t i = 0; i < trace.collisions.size(); ++i)
    if (trace.collisions[i].first == kEgo || trace.collisions[i].second == kEgo) return i;
  return std::nullopt;
}

ActorId counterpart(const Collision& collision) {
  return collision.first == kEgo ? collision.second : collision.first;
}

// Why the run says nothing about the driver; empty when it does.
std::string run_problem(const ScenarioRun& run) {
  if (!run.infeasible.empty()) return "the replay cannot be set up: " + run.infeasible;
  if (!run.trace) return "the replay could not be simulated: " + run.failure;
  if (const std::optional<EgoFailureReport> failure = ego_failure_report(*run.trace))
    if (ego_failed_to_start(*run.trace, *failure)) return failure->message;
  if (run.trace->end != EndReason::ego_failure && !run.failure.empty()) return run.failure;
  return "";
}

// Avoidability needs where the other went after the impact: the replay run on past collisions,
// its first collision of the ego with the same other judged. A driver (a plugin) that drives
// differently the second time leaves only the first run, whose trace ends at the impact.
Avoidability judge_avoidability(const ScenarioEvaluator& going_on, const Trace& stopped,
                                std::size_t collision, const RssParameters& rss) {
  const ScenarioRun again = going_on.run({}, kReplaySeed);
  if (again.trace)
    if (const std::optional<std::size_t> first = first_ego_collision(*again.trace))
      if (counterpart(again.trace->collisions[*first]) ==
          counterpart(stopped.collisions[collision]))
        return collision_avoidability(*again.trace, *first, rss);
  return collision_avoidability(stopped, collision, rss);
}

}  // namespace

std::string_view driver_verdict_name(DriverVerdict verdict) {
  switch (verdict) {
    case DriverVerdict::avoided: return "avoided";
    case DriverVerdict::unavoidable: return "unavoidable";
    case DriverVerdict::avoidable: return "avoidable";
    case DriverVerdict::caused: return "caused";
    case DriverVerdict::ego_failure: return "ego_failure";
  }
  SCENFUZZ_DEMAND(false);
  return {};
}

bool is_driver_finding(DriverVerdict verdict) {
  return verdict == DriverVerdict::avoidable || verdict == DriverVerdict::caused ||
         verdict == DriverVerdict::ego_failure;
}

DriverTest test_driver(const SourceFile& file, const ScenarioTemplate& replay,
                       MapSearchPath search_path, const SimulationOptions& simulation,
                       const JudgeOptions& judge) {
  ScenarioEvaluator evaluator(file, replay, search_path, simulation);
  evaluator.set_judge_options(judge);
  DriverTest test;
  test.run = evaluator.run({}, kReplaySeed);
  test.problem = run_problem(test.run);
  if (!test.problem.empty()) return test;
  const Trace& trace = *test.run.trace;
  if (trace.end == EndReason::ego_failure) {
    test.verdict = DriverVerdict::ego_failure;
    return test;
  }
  test.collision = first_ego_collision(trace);
  if (!test.collision) return test;
  for (const CollisionResponsibility& r : test.run.responsibilities)
    if (r.collision == *test.collision) test.responsibility = r;
  SCENFUZZ_DEMAND(test.responsibility.has_value());
  if (ego_responsible(test.responsibility->responsibility)) {
    test.verdict = DriverVerdict::caused;
    return test;
  }
  SimulationOptions going_on = simulation;
  going_on.stop_at_collision = false;
  ScenarioEvaluator again(file, replay, search_path, going_on);
  test.avoidability = judge_avoidability(again, trace, *test.collision, judge.rss);
  test.verdict =
      test.avoidability->avoidable ? DriverVerdict::avoidable : DriverVerdict::unavoidable;
  return test;
}

}  // namespace scenfuzz
