// Reached sub-violations of law specs: each spec's sub-violations evaluated on the trace through
// one TraceSignals whose leaves are cached, since the sub-violations of a law share their atoms.
#include "oracle/law_coverage.hpp"

#include <algorithm>
#include <limits>
#include <optional>
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

}  // namespace

bool is_law_spec(const Spec& spec) { return formula_reads_law_signal(spec.formula); }

std::string law_feature_name(const std::string& spec, std::size_t k, std::size_t count) {
  std::string number = std::to_string(k);
  const std::size_t width = std::to_string(count).size();
  if (number.size() < width) number.insert(0, width - number.size(), '0');
  return "law." + spec + "." + number;
}

std::vector<LawSubViolation> law_sub_violations(const ScenarioTemplate& scenario) {
  std::vector<LawSubViolation> all;
  for (std::size_t s = 0; s < scenario.specs.size(); ++s) {
    const Spec& spec = scenario.specs[s];
    if (!is_law_spec(spec)) continue;
    std::optional<std::vector<Formula>> subs = sub_violations(spec.formula);
    if (!subs) continue;
    for (std::size_t k = 0; k < subs->size(); ++k)
      all.push_back({s, law_feature_name(spec.name, k + 1, subs->size()), std::move((*subs)[k])});
  }
  return all;
}

std::vector<double> law_robustness(const std::vector<LawSubViolation>& subs,
                                   const ScenarioTemplate& scenario,
                                   std::span<const double> parameters, const Trace& trace,
                                   const RoadMap& map) {
  constexpr double never = -std::numeric_limits<double>::infinity();
  std::vector<double> robustness(subs.size(), never);
  if (subs.empty() || trace.sample_count() == 0 || trace.actors.empty()) return robustness;
  const TraceSignals signals(trace, scenario, parameters, map);
  CachedLeaves leaves(signals);
  const SignalSource source{trace.time, [&](const SpecTerm& term) { return leaves(term); },
                            parameters};
  for (std::size_t first = 0; first < subs.size();) {
    // One spec's sub-violations: a signal one of them cannot read leaves the whole spec unreached.
    std::size_t end = first;
    while (end < subs.size() && subs[end].spec == subs[first].spec) ++end;
    try {
      for (std::size_t k = first; k < end; ++k)
        robustness[k] = robustness_signal(subs[k].formula, source).front();
    } catch (const OracleError&) {
      std::fill(robustness.begin() + static_cast<std::ptrdiff_t>(first),
                robustness.begin() + static_cast<std::ptrdiff_t>(end), never);
    }
    first = end;
  }
  return robustness;
}

std::vector<std::string> reached_law_features(const std::vector<LawSubViolation>& subs,
                                              std::span<const double> robustness) {
  std::vector<std::string> features;
  for (std::size_t k = 0; k < subs.size() && k < robustness.size(); ++k)
    if (robustness[k] >= 0) features.push_back(subs[k].name);
  std::sort(features.begin(), features.end());
  return features;
}

std::vector<std::string> law_coverage(const ScenarioTemplate& scenario,
                                      std::span<const double> parameters, const Trace& trace,
                                      const RoadMap& map) {
  const std::vector<LawSubViolation> subs = law_sub_violations(scenario);
  return reached_law_features(subs, law_robustness(subs, scenario, parameters, trace, map));
}

}  // namespace scenfuzz
