// What the search explores, independent of scenarios: a box of parameters (the unit cube, one
// coordinate per dimension) and, at each point, one robustness per objective. Scenarios
// (ScenarioEvaluator) and the built-in benchmark systems (the ARCH-COMP chasing cars) both
// implement it, so one search engine drives both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace scenfuzz {

enum class GeneKind { continuous, angle, discrete };

struct SearchDimension {
  std::string name;  // "npc1.init.speed"
  GeneKind kind = GeneKind::continuous;
  std::size_t choices = 0;  // discrete: how many; the coordinate's cell picks one (decode())
  std::string group;        // the actor the dimension belongs to ("npc1"), for crossover
                            // that swaps whole actors; empty when none
  // The input signal this gene is one segment of ("throttle"), when the point parametrises a
  // signal over time by consecutive segments in order; empty otherwise. The GA then also holds
  // a value over a run of segments (a sustained input is rarely made of independent draws).
  std::string series;
};

struct Evaluation {
  // One per objective, in objectives() order; empty when the point was infeasible or failed.
  std::vector<double> robustness;
  // What the strategies minimise instead, when set (one per objective, negative exactly where
  // the robustness is): a conjunction's guide (oracle/search_guide.hpp).
  std::vector<double> guide;
  // Per objective, when the run's ends decided less than the trace ("time-out": not violated,
  // the robustness is what a longer run would give; "stuck": violated, the ego had stopped
  // making progress; "start-state": not violated, the robustness is the run's with its start
  // state excused; oracle/judge.hpp), else empty. Empty when no objective has one.
  std::vector<std::string> endings;
  // Set when the point was rejected before any simulation (actors overlapping at t = 0, a
  // position off every lane): such points do not count against the budget.
  std::string infeasible;
  // Set when the evaluation ran but could not be judged (an unplannable path, an ego plugin
  // that failed): it counts against the budget and has no robustness.
  std::string failure;
  // Set with `failure` when the failure is the system under test's own (a plugin that crashed,
  // hung or returned an error once started): the finding kind, "ego_crash", "ego_hang" or
  // "ego_error". Such an evaluation is a finding of that kind, never judged.
  std::string failure_kind;
  // The violated objectives, the earliest violation first (oracle/failure_mode.hpp).
  std::vector<std::size_t> violated;
  // The ego's first collision: whose fault ("ego", "other", "shared"; oracle/responsibility.hpp)
  // and why in one sentence; empty when it collided with nothing.
  std::string responsibility;
  std::string collision_reason;
  // The failure mode, which de-duplicates findings: a violation's signature
  // (oracle/failure_mode.hpp), an ego failure's kind and signal; empty when nothing failed (or
  // the evaluator names no modes: findings then go by the first violated objective).
  std::string signature;
  // What the simulated world did wrong (oracle/trace_audit.hpp): issues per AuditKind, counted
  // per search; empty when the evaluator audits nothing or nothing was simulated.
  std::vector<std::size_t> audit;
  // The behaviour-coverage features the run covered (docs/coverage.md), sorted and unique:
  // the search's summary reports their union. Empty when the evaluator computes none or the
  // run left no trace (fuzz/run_coverage.hpp).
  std::vector<std::string> coverage;
  // One per Evaluator::sub_targets(): the robustness at the trace's start of that law
  // sub-violation, >= 0 where the run reached it (the values `coverage`'s law features are read
  // from). Empty when the run left no trace or the evaluator has no sub-targets.
  std::vector<double> sub_robustness;
  double wall_seconds = 0;

  bool feasible() const { return infeasible.empty(); }
  bool judged() const { return infeasible.empty() && failure.empty(); }
};

// A law sub-violation (oracle/law_coverage.hpp) the search can target in place of its spec
// (--target sub-violations).
struct SubTarget {
  std::size_t objective = 0;  // its spec's index in objectives()
  std::string name;           // its coverage feature, "law.<spec>.<k>"
};

class Evaluator {
 public:
  virtual ~Evaluator() = default;
  virtual std::vector<SearchDimension> dimensions() const = 0;
  virtual std::vector<std::string> objectives() const = 0;
  // Where the search starts (a point of the unit cube): a concrete seed's values as written.
  // Nullopt: the strategies choose every point.
  virtual std::optional<std::vector<double>> start_point() const { return std::nullopt; }
  // The law sub-violations every evaluation measures (Evaluation::sub_robustness); none by default.
  virtual std::vector<SubTarget> sub_targets() const { return {}; }
  // The evaluation of `unit_point` with every random draw seeded from `seed`. Called from
  // several threads at once: implementations keep no mutable shared state.
  virtual Evaluation evaluate(std::span<const double> unit_point, std::uint64_t seed) const = 0;
};

}  // namespace scenfuzz
