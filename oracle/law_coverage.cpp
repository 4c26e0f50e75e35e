// Reached sub-violations of law specs: each spec's sub-violations evaluated on the trace through
// one TraceSignals whose leaves are cached, since the sub-violations of a law share their atoms.
#include "oracle/law_coverage.hpp"

#include <algorithm>
#include <utility>

#include "lang/avunit/builtins.hpp"
#include "oracle/robustness.hpp"
#include "oracle/sub_violations.hpp"
#include "oracle/trace_signals.hpp"

namespace scenfuzz {
namespace {

bool reads_law_signal(const SpecTerm& term) {
  if (term.kind == TermKind::signal) {
    const avunit::SignalClass kind = avunit::signal_class(term.name);
    if (kind == avunit::SignalClass::flag || kind == avunit::SignalClass::distance_predicate ||
        kind == avunit::SignalClass::value)
      return true;
    if (term.name == "acc" && term.operands.empty()) return true;  // scenest's acceleration
  }
  return std::any_of(term.operands.begin(), term.operands.end(), reads_law_signal);
}

bool formula_reads_law_signal(const Formula& formula) {
  return std::any_of(formula.terms.begin(), formula.terms.end(), reads_law_signal) ||
         std::any_of(formula.operands.begin(), formula.operands.end(), formula_reads_law_signal);
}

// The leaves computed so far, found by value: expansion copies a law's atoms into many formulas.
class CachedLeaves {
 public:
  explicit CachedLeaves(const TraceSignals& signals) : signals_(signals) {}

  const SignalValues& operator()(const SpecTerm& term) {
    for (const auto& [known, values] : cache_)
      if (known == term) return values;
    cache_.emplace_back(term, signals_.leaf(term));
    return cache_.back().second;
  }

 private:
  const TraceSignals& signals_;
  std::vector<std::pair<SpecTerm, SignalValues>> cache_;
};

// The reached sub-violations of one spec, appended to `features`; none when it cannot be judged.
void cover_spec(const Spec& spec, const SignalSource& source, std::vector<std::string>& features) {
  const std::optional<std::vector<Formula>> subs = sub_violations(spec.formula);
  if (!subs) return;
  std::vector<std::string> reached;
  try {
    for (std::size_t k = 0; k < subs->size(); ++k)
      if (robustness_signal((*subs)[k], source).front() >= 0)
        reached.push_back(law_feature_name(spec.name, k + 1, subs->size()));
  } catch (const OracleError&) {
    return;
  }
  features.insert(features.end(), reached.begin(), reached.end());
}

}  // namespace

bool is_law_spec(const Spec& spec) { return formula_reads_law_signal(spec.formula); }

std::string law_feature_name(const std::string& spec, std::size_t k, std::size_t count) {
  std::string number = std::to_string(k);
  const std::size_t width = std::to_string(count).size();
  if (number.size() < width) number.insert(0, width - number.size(), '0');
  return "law." + spec + "." + number;
}

std::vector<std::string> law_coverage(const ScenarioTemplate& scenario,
                                      std::span<const double> parameters, const Trace& trace,
                                      const RoadMap& map) {
  std::vector<std::string> features;
  if (trace.sample_count() == 0 || trace.actors.empty()) return features;
  const TraceSignals signals(trace, scenario, parameters, map);
  CachedLeaves leaves(signals);
  const SignalSource source{trace.time, [&](const SpecTerm& term) { return leaves(term); },
                            parameters};
  for (const Spec& spec : scenario.specs)
    if (is_law_spec(spec)) cover_spec(spec, source, features);
  std::sort(features.begin(), features.end());
  return features;
}

}  // namespace scenfuzz
