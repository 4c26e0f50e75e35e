#include "oracle/judge.hpp"

#include "oracle/collision_oracle.hpp"
#include "oracle/robustness.hpp"
#include "oracle/search_guide.hpp"
#include "oracle/trace_signals.hpp"

namespace scenfuzz {

namespace {

double time_of_sample(const Trace& trace, std::size_t sample) {
  return sample < trace.time.size() ? trace.time[sample] : 0.0;
}

SpecVerdict no_collision_verdict(const Trace& trace) {
  const CollisionVerdict collision = collision_verdict(trace);
  SpecVerdict verdict;
  verdict.name = kNoCollisionSpec;
  verdict.robustness = collision.robustness;
  verdict.guide = collision.robustness;
  verdict.time = time_of_sample(trace, collision.sample);
  verdict.atom_text = collision.other == kEgo ? "the ego is alone"
                                              : "the ego and " + trace.actors[collision.other].name;
  return verdict;
}

}  // namespace

std::vector<SpecVerdict> judge_trace(const ScenarioTemplate& scenario,
                                     std::span<const double> parameters, const Trace& trace,
                                     const RoadMap& map, const SourceFile& file) {
  if (scenario.specs.empty()) return {no_collision_verdict(trace)};
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
