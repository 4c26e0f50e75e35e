// Quantitative STL semantics over sampled signals (DESIGN.md "Semantics", RTAMT's discrete-time
// conventions): the robustness of a formula at every sample, computed bottom-up with one
// linear-time pass per operator (two-stack sliding windows for bounded G and F, van Herk /
// Gil-Werman where the sampling is uniform, a backward pass for unbounded U, the
// Donze-Ferrere-Maler decomposition for bounded U).
//
// The oracle knows numbers, enumeration words, times of day, arithmetic and the operators; what a
// named signal means (a CSV column, `dis(a, b)` over a simulated trace, ...) comes from a
// SignalSource.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/spec.hpp"

namespace scenfuzz {

// A spec that cannot be judged on the data it meets (an unknown column, a signal the oracle
// cannot compute, a value that is not a number): the message and the place in the spec.
class OracleError : public std::runtime_error {
 public:
  OracleError(SourceLocation location, const std::string& message)
      : std::runtime_error(message), location_(location) {}
  const SourceLocation& location() const { return location_; }

 private:
  SourceLocation location_;
};

// A numeric signal: one value per sample. `discrete` marks flags and enumerations: a comparison
// whose two sides are both discrete has robustness +1 when true and -1 when false.
struct SignalValues {
  std::vector<double> values;
  bool discrete = false;
};

// A sample j is in the window [a, b] of sample i when a <= t_j - t_i <= b up to this slack
// (seconds), so that sample times such as 0.1 + 0.2 fall where they are meant to.
inline constexpr double kWindowTolerance = 1e-9;

// Gives a TermKind::signal or TermKind::column term (with its arguments: `dis(a, b)`, `speed`,
// a CSV column `x`, `ego_state.speed`) its value at every sample. Must return time.size() finite
// values, or throw OracleError naming the term's location.
using LeafSignal = std::function<SignalValues(const SpecTerm& term)>;

struct SignalSource {
  std::span<const double> time;        // sample times in seconds, strictly increasing
  LeafSignal leaf;                     // named signals
  std::span<const double> parameters;  // values of the search parameters a term's Value reads
};

// The numeric value of `term` at every sample: numbers, times of day (seconds since midnight),
// enumeration words (LawBreaker's codes: red 1, yellow 2, green 3, off/forward 0, left 1,
// right 2; discrete), arithmetic, and leaves through `source.leaf`. Throws OracleError.
SignalValues term_signal(const SpecTerm& term, const SignalSource& source);

// The robustness of `formula` at every sample of `source.time` (+inf and -inf where the
// semantics give them). Throws OracleError.
std::vector<double> robustness_signal(const Formula& formula, const SignalSource& source);

// The robustness at the first sample were the trace to go on past its last sample in whatever
// way serves the formula best: every atom +inf there (-inf under an odd number of negations), for
// `horizon` seconds (spec_horizon.hpp; at most as long again as the trace) at the trace's last
// step. Weak semantics at the end: below zero only when what was observed violates the formula
// whatever came next; the robustness below zero and this not means the trace ended too early to
// tell (an F whose window the end cut off). Throws OracleError.
double robustness_if_continued(const Formula& formula, const SignalSource& source, double horizon);

// The robustness at the first sample had the trace ended after its first `samples` samples,
// continued from there as robustness_if_continued does: what the trace had decided before
// something that came after it (another road user's fault, docs/oracle.md "Not the ego's
// fault"). +inf when `samples` is 0: nothing observed violates anything. Throws OracleError.
double robustness_before(const Formula& formula, const SignalSource& source, std::size_t samples,
                         double horizon);

// The robustness at the first sample with every sample within `grace` seconds of the first
// excused: the start state the scenario gave the trace, not what the trace did with it. Mirrors
// robustness_if_continued at the other end: every atom there +inf (-inf under an odd number of
// negations), but only where no existential operator reads it (F, G under an odd number of
// negations, U): a G no longer counts those samples against the formula, while an F still counts
// what they did for it and is never satisfied by them (the start cannot fulfil an F: `F[0, 1]`
// wholly within the grace is judged on the samples as they are). Throws OracleError.
double robustness_if_started_later(const Formula& formula, const SignalSource& source,
                                   double grace);

// Both at once: the first `start` seconds excused as robustness_if_started_later does them, and,
// when `end_horizon` is set, the trace continued past its end as robustness_if_continued does.
struct ExcusedSamples {
  double start = 0;                   // seconds from the first sample
  std::optional<double> end_horizon;  // seconds past the last (spec_horizon.hpp)
};
double robustness_excusing(const Formula& formula, const SignalSource& source,
                           const ExcusedSamples& excused);

// Why a formula has the robustness it has at a sample: following min and max down the formula,
// the atom (comparison or predicate) and the sample whose value it is.
struct RobustnessWitness {
  double robustness = 0;          // of the whole formula at the sample asked about
  const Formula* atom = nullptr;  // the responsible atom; null when the value is an infinity
                                  // that no atom gives (an empty window, X at the last sample)
  std::size_t sample = 0;         // where the atom has that value
};

// The robustness at `sample` (0: the spec's verdict) and its witness. Throws OracleError.
RobustnessWitness explain_robustness(const Formula& formula, const SignalSource& source,
                                     std::size_t sample = 0);

// robustness_if_started_later's value and its witness: what the trace did once the first
// `grace` seconds are excused, the driver's share of a violation the start state also had a
// hand in (docs/oracle.md, "Start state"). The start alone: a decided violation is not the end's
// doing, so its end is taken as observed. Throws OracleError.
RobustnessWitness explain_robustness_if_started_later(const Formula& formula,
                                                      const SignalSource& source, double grace);

}  // namespace scenfuzz
