#include "oracle/judge.hpp"

#include <algorithm>
#include <cmath>

#include "oracle/collision_oracle.hpp"
#include "oracle/robustness.hpp"
#include "oracle/search_guide.hpp"
#include "oracle/trace_signals.hpp"

namespace scenfuzz {

namespace {

double time_of_sample(const Trace& trace, std::size_t sample) {
  return sample < trace.time.size() ? trace.time[sample] : 0.0;
}

// Per actor, the sample from which the collision oracle leaves it out: its first collision with
// the ego that was not the ego's fault (RSS, oracle/responsibility); never with --all-collisions.
std::vector<std::size_t> excused_from(const Trace& trace, const RoadMap& map,
                                      const JudgeOptions& options, std::string& excused) {
  std::vector<std::size_t> from(trace.actors.size(), trace.sample_count());
  if (options.all_collisions || trace.sample_count() == 0) return from;
  for (const CollisionResponsibility& r : ego_collision_responsibilities(trace, map, options.rss)) {
    if (ego_responsible(r.responsibility) || from[r.other] < trace.sample_count()) continue;
    from[r.other] = std::min(
        trace.sample_count() - 1,
        static_cast<std::size_t>(std::llround(trace.collisions[r.collision].time / trace.dt)));
    excused += (excused.empty() ? "" : ", ") + trace.actors[r.other].name;
  }
  return from;
}

SpecVerdict no_collision_verdict(const Trace& trace, const RoadMap& map,
                                 const JudgeOptions& options) {
  std::string excused;
  const std::vector<std::size_t> from = excused_from(trace, map, options, excused);
  const CollisionVerdict collision = collision_verdict(trace, from);
  SpecVerdict verdict;
  verdict.name = kNoCollisionSpec;
  verdict.robustness = collision.robustness;
  verdict.guide = collision.robustness;
  verdict.time = time_of_sample(trace, collision.sample);
  verdict.atom_text = collision.other == kEgo ? "the ego is alone"
                                              : "the ego and " + trace.actors[collision.other].name;
  if (!excused.empty())
    verdict.atom_text += " (not counted: a collision not the ego's fault with " + excused + ")";
  return verdict;
}

}  // namespace

std::vector<SpecVerdict> judge_trace(const ScenarioTemplate& scenario,
                                     std::span<const double> parameters, const Trace& trace,
                                     const RoadMap& map, const SourceFile& file,
                                     const JudgeOptions& options) {
  if (scenario.specs.empty()) return {no_collision_verdict(trace, map, options)};
  const TraceSignals signals(trace, scenario, parameters, map);
  const SignalSource source = signals.source();
  std::vector<SpecVerdict> verdicts;
  for (const Spec& spec : scenario.specs) {
    const RobustnessWitness witness = explain_robustness(spec.formula, source);
    SpecVerdict verdict;
    verdict.name = spec.name;
    verdict.robustness = witness.robustness;
    verdict.guide = witness.robustness;
    if (const std::vector<Formula> conjuncts = top_level_conjuncts(spec.formula);
        conjuncts.size() > 1) {
      std::vector<double> robustness;
      for (const Formula& conjunct : conjuncts)
        robustness.push_back(robustness_signal(conjunct, source).front());
      verdict.guide = conjunct_guide(robustness);
    }
    verdict.time = time_of_sample(trace, witness.sample);
    if (witness.atom) {
      verdict.atom = witness.atom->location;
      if (verdict.atom.known() && verdict.atom.end_offset() <= file.text().size())
        verdict.atom_text = file.text().substr(verdict.atom.offset, verdict.atom.length);
    }
    verdicts.push_back(std::move(verdict));
  }
  return verdicts;
}

}  // namespace scenfuzz
