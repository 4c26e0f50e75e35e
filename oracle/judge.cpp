#include "oracle/judge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "lang/spec_horizon.hpp"
#include "oracle/collision_oracle.hpp"
#include "oracle/ego_progress.hpp"
#include "oracle/robustness.hpp"
#include "oracle/rss_response.hpp"
#include "oracle/search_guide.hpp"
#include "oracle/trace_signals.hpp"

namespace scenfuzz {

namespace {

double time_of_sample(const Trace& trace, std::size_t sample) {
  return sample < trace.time.size() ? trace.time[sample] : 0.0;
}

// The sample of an event at `time` (a collision's), within the trace.
std::size_t sample_of_time(const Trace& trace, double time) {
  return std::min(trace.sample_count() - 1,
                  static_cast<std::size_t>(std::llround(time / trace.dt)));
}

// Per actor, the sample from which the collision oracle leaves it out: its first collision with
// the ego that was not the ego's fault (RSS, oracle/responsibility); never with --all-collisions.
std::vector<std::size_t> excused_from(const Trace& trace, const RoadMap& map,
                                      const JudgeOptions& options, std::string& excused) {
  std::vector<std::size_t> from(trace.actors.size(), trace.sample_count());
  if (options.all_collisions || trace.sample_count() == 0) return from;
  for (const CollisionResponsibility& r : ego_collision_responsibilities(trace, map, options.rss)) {
    if (ego_responsible(r.responsibility) || from[r.other] < trace.sample_count()) continue;
    from[r.other] = sample_of_time(trace, trace.collisions[r.collision].time);
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

// The robustness of `formula`, or for a conjunction its conjunct guide, from the robustness of
// each conjunct: as observed, or with the samples `excused` excuses (an end horizon set: each
// conjunct's own).
double guide_of(const Formula& formula, const SignalSource& source, double robustness,
                const std::optional<ExcusedSamples>& excused) {
  const std::vector<Formula> conjuncts = top_level_conjuncts(formula);
  if (conjuncts.size() <= 1) return robustness;
  std::vector<double> values;
  for (const Formula& conjunct : conjuncts) {
    if (!excused) {
      values.push_back(robustness_signal(conjunct, source).front());
      continue;
    }
    ExcusedSamples own = *excused;
    if (own.end_horizon) own.end_horizon = formula_horizon(conjunct);
    values.push_back(robustness_excusing(conjunct, source, own));
  }
  return conjunct_guide(values);
}

bool violates(const SpecVerdict& verdict, double robustness) {
  return robustness < 0 || (verdict.zero_violates && robustness == 0);
}

// The ego's progress at the end of the run, computed once and only when a verdict asks.
class LazyProgress {
 public:
  LazyProgress(const Trace& trace, const ScenarioTemplate& scenario,
               std::span<const double> parameters, const RoadMap& map)
      : trace_(trace), scenario_(scenario), parameters_(parameters), map_(map) {}

  const EgoProgress& get() {
    if (!progress_) progress_ = ego_progress_at_end(trace_, scenario_, parameters_, map_);
    return *progress_;
  }

 private:
  const Trace& trace_;
  const ScenarioTemplate& scenario_;
  std::span<const double> parameters_;
  const RoadMap& map_;
  std::optional<EgoProgress> progress_;
};

// A violation of a run that ended at its duration that a longer run might not have had: a
// time-out while the ego progressed, else stuck.
void judge_the_end(const Spec& spec, const SignalSource& source, LazyProgress& progress,
                   SpecVerdict& verdict) {
  const double continued =
      robustness_if_continued(spec.formula, source, formula_horizon(spec.formula));
  if (violates(verdict, continued)) return;
  verdict.progress = progress.get().description;
  if (progress.get().stuck) {
    verdict.ending = VerdictEnding::stuck;
    return;
  }
  verdict.ending = VerdictEnding::time_out;
  verdict.robustness_as_observed = verdict.robustness;
  verdict.robustness = continued;
  verdict.guide = guide_of(spec.formula, source, continued, ExcusedSamples{0, 0.0});
}

std::string atom_text(const SourceFile& file, const SourceLocation& atom) {
  if (!atom.known() || atom.end_offset() > file.text().size()) return "";
  return file.text().substr(atom.offset, atom.length);
}

// The nodes from `node` down to `target` (a node of its tree), or false when it is not there.
bool path_to(const Formula& node, const Formula& target, std::vector<const Formula*>& path) {
  path.push_back(&node);
  if (&node == &target) return true;
  for (const Formula& operand : node.operands)
    if (path_to(operand, target, path)) return true;
  path.pop_back();
  return false;
}

// What names a violation's failure mode: its atom, unless a disjunction or implication lies
// above it (then which side gave the value is happenstance: `near -> slow` is violated by
// `near` and `slow` together), when the highest such subformula as written.
std::string mode_text(const SourceFile& file, const Formula& root, const Formula& atom,
                      const std::string& atom_text_) {
  std::vector<const Formula*> path;
  if (!path_to(root, atom, path)) return atom_text_;
  for (const Formula* node : path)
    if (node->kind == FormulaKind::disjunction || node->kind == FormulaKind::implication) {
      std::string text = atom_text(file, node->location);
      return text.size() > atom_text_.size() ? text : atom_text_;
    }
  return atom_text_;
}

// When the window of an F at t = 0 closes: its upper bound, or the end of the run.
double window_end(const Formula& eventually, const Trace& trace) {
  const double end = trace.time.empty() ? 0.0 : trace.time.back();
  return eventually.interval ? std::min(end, eventually.interval->upper) : end;
}

bool reads_actor_distance(const SpecTerm& term) {
  if (term.kind == TermKind::signal && term.name == "dis" && term.operands.size() == 2 &&
      term.operands[0].kind == TermKind::object && term.operands[1].kind == TermKind::object)
    return true;
  return std::any_of(term.operands.begin(), term.operands.end(), reads_actor_distance);
}

// Whether an atom compares the distance between two road users (SpecVerdict::actor_distance).
bool reads_actor_distance(const Formula& atom) {
  return std::any_of(atom.terms.begin(), atom.terms.end(),
                     [](const SpecTerm& term) { return reads_actor_distance(term); });
}

// Whether a violation at `time` is one the scenario's start state may have made: within the
// grace, of a run that went on past it (one that ended within it, e.g. by a collision, has no
// "from then on" to hold on).
bool within_grace(double time, const Trace& trace, const JudgeOptions& options) {
  const double grace = options.start_grace - kWindowTolerance;
  return time < grace && !trace.time.empty() && trace.time.back() >= grace;
}

// The atom that gives `witness` its value, as `named`'s atom, its text, failure mode and whether
// it reads a distance between road users (the fields SpecVerdict and ViolatedConjunct share);
// none when an infinity no atom gives is the value. `root` is the formula the witness is of.
template <class Named>
void name_atom(const SourceFile& file, const Formula& root, const RobustnessWitness& witness,
               Named& named) {
  named.atom = {};
  named.atom_text.clear();
  named.mode_text.clear();
  named.actor_distance = false;
  if (!witness.atom) return;
  named.atom = witness.atom->location;
  named.atom_text = atom_text(file, named.atom);
  named.mode_text = mode_text(file, root, *witness.atom, named.atom_text);
  named.actor_distance = reads_actor_distance(*witness.atom);
}

// A violated conjunct as `witness` explains it. An F is violated when its window closes, not
// where it came nearest to holding.
ViolatedConjunct violated_conjunct(const Formula& conjunct, const RobustnessWitness& witness,
                                   const Trace& trace, const SourceFile& file) {
  ViolatedConjunct violated;
  violated.eventually = conjunct.kind == FormulaKind::eventually;
  violated.robustness = witness.robustness;
  violated.time =
      violated.eventually ? window_end(conjunct, trace) : time_of_sample(trace, witness.sample);
  name_atom(file, conjunct, witness, violated);
  return violated;
}

// A violated conjunction's violated conjuncts, the earliest first, and the verdict's atom and
// time the first's. A conjunct violated only because the run ended (its robustness were the
// run to go on is not negative) is left out unless the ego was stuck; one only the scenario's
// start state violated (judge_the_start's rule, for the conjunct alone, its end continued too
// when the run was cut short) is left out too, and names the verdict's atom and time only when
// no conjunct is left: then every violation is the ends' doing. One violated within the grace
// that the start state only made worse is named by the driver's share (take_the_drivers_share,
// for the conjunct alone): its robustness, time and atom once the grace is excused.
void name_violated_conjuncts(const Spec& spec, const SignalSource& source, const Trace& trace,
                             const SourceFile& file, const JudgeOptions& options,
                             SpecVerdict& verdict) {
  const std::vector<Formula> conjuncts = top_level_conjuncts(spec.formula);
  if (conjuncts.size() <= 1) return;
  const bool cut_short = trace.end == EndReason::duration && verdict.ending != VerdictEnding::stuck;
  std::vector<ViolatedConjunct> start_states;
  for (const Formula& conjunct : conjuncts) {
    const RobustnessWitness witness = explain_robustness(conjunct, source);
    if (!(witness.robustness < 0)) continue;
    if (cut_short && robustness_if_continued(conjunct, source, formula_horizon(conjunct)) >= 0)
      continue;
    ViolatedConjunct violated = violated_conjunct(conjunct, witness, trace, file);
    if (within_grace(violated.time, trace, options)) {
      const ExcusedSamples excused{
          options.start_grace, cut_short ? std::optional(formula_horizon(conjunct)) : std::nullopt};
      if (!violates(verdict, robustness_excusing(conjunct, source, excused))) {
        start_states.push_back(std::move(violated));
        continue;
      }
      const RobustnessWitness share =
          explain_robustness_if_started_later(conjunct, source, options.start_grace);
      if (share.robustness > witness.robustness)
        violated = violated_conjunct(conjunct, share, trace, file);
    }
    verdict.conjuncts.push_back(std::move(violated));
  }
  for (std::vector<ViolatedConjunct>* list : {&verdict.conjuncts, &start_states})
    std::stable_sort(list->begin(), list->end(),
                     [](const ViolatedConjunct& a, const ViolatedConjunct& b) {
                       return a.time != b.time ? a.time < b.time : !a.eventually && b.eventually;
                     });
  const std::vector<ViolatedConjunct>& named =
      verdict.conjuncts.empty() ? start_states : verdict.conjuncts;
  if (named.empty()) return;
  verdict.time = named.front().time;
  verdict.atom = named.front().atom;
  verdict.atom_text = named.front().atom_text;
  verdict.mode_text = named.front().mode_text;
  verdict.actor_distance = named.front().actor_distance;
}

// A violation the scenario's start state made: the trace violates the spec within the grace and
// not once its first seconds are excused (robustness_if_started_later); start-state, not a
// violation. Judged after the time-out rule, on what it left violated: when the run ended at its
// duration the end is continued too, so a run both started and ended out of line is start-state
// while the ego progressed at its end, stuck (a violation) when it did not.
void judge_the_start(const Spec& spec, const SignalSource& source, const Trace& trace,
                     const SourceFile& file, LazyProgress& progress, const JudgeOptions& options,
                     SpecVerdict& verdict) {
  // A conjunct the trace violates beyond the start's doing is the driver's (the start-state
  // conjuncts are not among verdict.conjuncts).
  if (verdict.ending != VerdictEnding::decided || !verdict.violated() ||
      !verdict.conjuncts.empty() || !within_grace(verdict.time, trace, options))
    return;
  ExcusedSamples excused{options.start_grace, std::nullopt};
  double robustness = robustness_excusing(spec.formula, source, excused);
  if (violates(verdict, robustness) && trace.end == EndReason::duration) {
    excused.end_horizon = formula_horizon(spec.formula);
    robustness = robustness_excusing(spec.formula, source, excused);
    if (violates(verdict, robustness)) return;
    verdict.progress = progress.get().description;
    if (progress.get().stuck) {
      // The end's part of it is the ego's: every violated conjunct counts, as for stuck.
      verdict.ending = VerdictEnding::stuck;
      verdict.conjuncts.clear();
      name_violated_conjuncts(spec, source, trace, file, options, verdict);
      return;
    }
  }
  if (violates(verdict, robustness)) return;
  verdict.ending = VerdictEnding::start;
  verdict.robustness_as_observed = verdict.robustness;
  verdict.robustness = robustness;
  verdict.guide = guide_of(spec.formula, source, robustness, excused);
  verdict.conjuncts.clear();  // none is a violation
}

// A decided violation the start state made worse: its worst (`observed`) lies within the grace,
// the trace violates the spec with the grace excused too (else judge_the_start made it
// start-state), but less. A finding must not blame the driver for the file's start, so the
// verdict reports the driver's share, what the trace did from the grace on
// (SpecVerdict::start_excused): its robustness and, unless conjuncts name them (each its own
// share), its time and atom. A worst the excused trace equals (a violation as bad from the start
// to the end, an F's value, which excusing leaves as it was) stands as observed: the start made
// it no worse. Only the start is excused: a decided violation is not the end's doing. The guide
// stays: negative as the robustness is, and the search's landscape is not reshaped by a report.
void take_the_drivers_share(const Spec& spec, const SignalSource& source, const Trace& trace,
                            const SourceFile& file, const JudgeOptions& options,
                            const RobustnessWitness& observed, SpecVerdict& verdict) {
  const double observed_time = time_of_sample(trace, observed.sample);
  if (verdict.ending != VerdictEnding::decided || !verdict.violated() ||
      !within_grace(observed_time, trace, options))
    return;
  const RobustnessWitness share =
      explain_robustness_if_started_later(spec.formula, source, options.start_grace);
  if (!(share.robustness > observed.robustness) || !violates(verdict, share.robustness)) return;
  verdict.start_excused = true;
  verdict.robustness_as_observed = verdict.robustness;
  verdict.time_as_observed = observed_time;
  verdict.robustness = share.robustness;
  if (!verdict.conjuncts.empty()) return;
  verdict.time = time_of_sample(trace, share.sample);
  name_atom(file, spec.formula, share, verdict);
}

// How long before an impact the ego's first collision, when not the ego's fault, excuses what the
// trace did at most: a conflict is critical within 3 s of impact (the time-to-collision threshold
// of the traffic-conflict literature), what the ego did before is its own driving.
constexpr double kDangerWindow = 3.0;  // s

// The ego's first collision when it was not the ego's fault: who, and the sample from which the
// danger it brought is excused: the earlier of when that road user came into the ego's path and
// RSS's blame time (when the situation last became dangerous), but no earlier than kDangerWindow
// before the impact. None with --all-collisions.
struct OthersFault {
  ActorId other = kEgo;
  std::size_t from = 0;
};

std::optional<OthersFault> others_fault(const Trace& trace, const RoadMap& map,
                                        const JudgeOptions& options) {
  if (options.all_collisions || trace.sample_count() == 0) return std::nullopt;
  const auto first = std::find_if(trace.collisions.begin(), trace.collisions.end(),
                                  [](const Collision& c) { return c.first == kEgo; });
  if (first == trace.collisions.end()) return std::nullopt;
  const auto index = static_cast<std::size_t>(first - trace.collisions.begin());
  const CollisionResponsibility r = collision_responsibility(trace, map, index, options.rss);
  if (ego_responsible(r.responsibility)) return std::nullopt;
  const std::size_t contact = sample_of_time(trace, first->time);
  std::size_t from = rss_blame_time(trace, map, r.other, contact, options.rss).sample;
  if (r.triage.entry) from = std::min(from, r.triage.entry->sample);
  const auto window = static_cast<std::size_t>(std::llround(kDangerWindow / trace.dt));
  from = std::max(from, contact > window ? contact - window : 0);
  return OthersFault{r.other, std::min(from, contact)};
}

// A decided violation the trace had not decided before another road user brought the danger of
// a collision that was not the ego's fault: that road user's doing, as the collision oracle
// leaves such a collision out (docs/oracle.md, "Not the ego's fault"). What the ego did before
// still counts: a spec it broke earlier stays violated.
void judge_the_collision(const Spec& spec, const SignalSource& source, const Trace& trace,
                         const std::optional<OthersFault>& fault, SpecVerdict& verdict) {
  if (!fault || verdict.ending != VerdictEnding::decided || !verdict.violated()) return;
  const double before =
      robustness_before(spec.formula, source, fault->from, formula_horizon(spec.formula));
  if (violates(verdict, before)) return;
  verdict.ending = VerdictEnding::other_fault;
  verdict.robustness_as_observed = verdict.robustness;
  verdict.robustness = before;
  verdict.guide = before;
  verdict.other = trace.actors[fault->other].name;
  verdict.danger_from = time_of_sample(trace, fault->from);
  verdict.conjuncts.clear();  // none is a violation
}

// One spec's verdict. Throws OracleError when the trace cannot answer it.
SpecVerdict judge_spec(const Spec& spec, const SignalSource& source, const Trace& trace,
                       const SourceFile& file, LazyProgress& progress,
                       const std::optional<OthersFault>& fault, const JudgeOptions& options) {
  const RobustnessWitness witness = explain_robustness(spec.formula, source);
  SpecVerdict verdict;
  verdict.name = spec.name;
  verdict.zero_violates = options.violation_at_zero;
  verdict.robustness = witness.robustness;
  verdict.guide = guide_of(spec.formula, source, witness.robustness, std::nullopt);
  if (verdict.violated() && trace.end == EndReason::duration)
    judge_the_end(spec, source, progress, verdict);
  verdict.time = time_of_sample(trace, witness.sample);
  name_atom(file, spec.formula, witness, verdict);
  if (verdict.violated()) name_violated_conjuncts(spec, source, trace, file, options, verdict);
  judge_the_start(spec, source, trace, file, progress, options, verdict);
  judge_the_collision(spec, source, trace, fault, verdict);
  take_the_drivers_share(spec, source, trace, file, options, witness, verdict);
  return verdict;
}

}  // namespace

std::string_view verdict_ending_name(VerdictEnding ending) {
  switch (ending) {
    case VerdictEnding::decided: return "decided";
    case VerdictEnding::time_out: return "time-out";
    case VerdictEnding::stuck: return "stuck";
    case VerdictEnding::start: return "start-state";
    case VerdictEnding::other_fault: return "other-fault";
  }
  return "decided";
}

std::vector<SpecVerdict> judge_trace(const ScenarioTemplate& scenario,
                                     std::span<const double> parameters, const Trace& trace,
                                     const RoadMap& map, const SourceFile& file,
                                     const JudgeOptions& options) {
  if (scenario.specs.empty()) {
    SpecVerdict verdict = no_collision_verdict(trace, map, options);
    verdict.zero_violates = options.violation_at_zero;
    return {verdict};
  }
  const TraceSignals signals(trace, scenario, parameters, map);
  const SignalSource source = signals.source();
  LazyProgress progress(trace, scenario, parameters, map);
  const std::optional<OthersFault> fault = others_fault(trace, map, options);
  std::vector<SpecVerdict> verdicts;
  for (const Spec& spec : scenario.specs) {
    try {
      verdicts.push_back(judge_spec(spec, source, trace, file, progress, fault, options));
    } catch (const OracleError& error) {
      SpecVerdict verdict;
      verdict.name = spec.name;
      verdict.robustness = std::numeric_limits<double>::quiet_NaN();
      verdict.guide = verdict.robustness;
      verdict.not_judged = error.what();
      verdict.not_judged_at = error.location();
      verdicts.push_back(std::move(verdict));
    }
  }
  return verdicts;
}

}  // namespace scenfuzz
