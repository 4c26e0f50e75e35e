// Judging a run: every spec of the scenario evaluated on its trace, or, when the scenario has no
// spec, the collision oracle. What the search minimises and what `scenfuzz run` reports.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/scenario.hpp"
#include "lang/source_file.hpp"
#include "oracle/responsibility.hpp"
#include "oracle/rss_parameters.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// The name the collision oracle's verdict carries.
inline constexpr const char* kNoCollisionSpec = "no_collision";

// How the ends of the run bear on a verdict (docs/oracle.md, "Time-outs" and "Start state").
enum class VerdictEnding {
  decided,  // the trace decides the spec
  // Violated only because the run ended at its duration (robustness_if_continued is not
  // negative: an `F` the end cut off) while the ego was still making progress: not a violation.
  time_out,
  // The same, but the ego had stopped making progress (ego_progress.hpp): a violation.
  stuck,
  // Violated within JudgeOptions::start_grace of the start and not once those first seconds are
  // excused (robustness_if_started_later): the scenario's start state broke the spec, not the
  // driver. Not a violation.
  start,
  // Violated only from when the road user in the ego's first collision, not the ego's fault
  // (oracle/responsibility), brought the danger (robustness_before that time is not a
  // violation): that road user's doing. Not a violation; never with --all-collisions.
  other_fault,
};

// "decided", "time-out", "stuck", "start-state", "other-fault".
std::string_view verdict_ending_name(VerdictEnding ending);

// One violated conjunct of a spec that is a conjunction (`a & b & c` at its top level).
struct ViolatedConjunct {
  bool eventually = false;  // an F: violated when its window closes, last among equal times
  double robustness = 0;
  double time = 0;
  SourceLocation atom;
  std::string atom_text;
  std::string mode_text;        // what names its failure mode (see SpecVerdict)
  bool actor_distance = false;  // see SpecVerdict
};

struct SpecVerdict {
  std::string name;       // the spec's name, or kNoCollisionSpec
  double robustness = 0;  // at t = 0; +inf/-inf possible
  double time = 0;        // when the responsible atom has that value (the collision oracle: when
                          // the ego is nearest to another body)
  SourceLocation atom;    // the responsible atom in the file; unknown for the collision oracle
                          // and for an infinity no atom gives
  std::string atom_text;  // that atom as written, or for the collision oracle which bodies
  // What names the failure mode: the atom, or, when a disjunction or implication lies above it
  // (which side gave the value is then happenstance), the highest such subformula as written.
  std::string mode_text;
  // Whether the responsible atom reads the distance between two road users (`dis(a, b)` of two
  // trace projections): violated without contact, a near miss (failure_mode.hpp).
  bool actor_distance = false;
  // What a search minimises: the robustness, or for a conjunction the conjunct guide
  // (search_guide.hpp); negative exactly when the robustness is.
  double guide = 0;
  VerdictEnding ending = VerdictEnding::decided;
  // A time-out or start-state: `robustness` and `guide` are what the run gives with its end
  // continued as the spec needs, or its start excused (never violations); this is the robustness
  // of the trace as it was observed (a violation). With start_excused: the observed robustness,
  // which the start state made worse than the driver's share.
  double robustness_as_observed = 0;
  // A decided violation whose worst lies within JudgeOptions::start_grace and that the trace
  // still violates once those seconds are excused, but less: the start state made it worse, the
  // driver did the rest. `robustness`, `time` and the atom are the driver's share (the start
  // excused, still a violation), so that a finding does not blame the driver for the file's
  // start; robustness_as_observed and time_as_observed are the worst as observed. `guide` stays
  // the observed one's (negative all the same).
  bool start_excused = false;
  double time_as_observed = 0;  // with start_excused: when the observed worst was
  // other_fault: who collided with the ego and when the danger it brought began; `robustness`
  // and `guide` are the trace's up to then (robustness_before), robustness_as_observed as above.
  std::string other;
  double danger_from = 0;
  // A time-out or stuck: the ego's progress over the end of the run, in words.
  std::string progress;
  // A violated conjunction: every conjunct the trace violates (not those only the run's end
  // cut short), the earliest first; `time`, `atom` and `atom_text` above are the first's, so a
  // crash is never reported as the target a later conjunct missed. Empty otherwise.
  std::vector<ViolatedConjunct> conjuncts;
  // Why the trace cannot answer the spec (a signal the oracle does not compute, an actor the
  // trace lacks), at not_judged_at; empty when judged. `robustness` is then NaN.
  std::string not_judged;
  SourceLocation not_judged_at;

  // LawBreaker's convention (JudgeOptions::violation_at_zero): robustness 0 is violated too.
  bool zero_violates = false;

  bool judged() const { return not_judged.empty(); }
  bool violated() const {
    return judged() && (robustness < 0 || (zero_violates && robustness == 0));
  }
};

// How the collision oracle treats collisions that are not the ego's fault (oracle/responsibility),
// and which robustness is a violation.
struct JudgeOptions {
  RssParameters rss;
  bool all_collisions = false;  // --all-collisions: count them too, and judge specs on them
                                // (no VerdictEnding::other_fault)
  // --violation-at-zero: robustness exactly 0 is a violation (LawBreaker: the negated formula's
  // robustness >= 0), not satisfied (RTAMT's convention, the default).
  bool violation_at_zero = false;
  // Seconds from the start in which a violation may be the scenario's start state's
  // (VerdictEnding::start): what a driver needs to bring a file's start state into line, a
  // reaction (RSS's 1 s) plus a comfortable correction (1 s at 2 m/s^2 takes 7 km/h off).
  double start_grace = 2.0;
};

// One verdict per spec of `scenario`, in file order, or one from the collision oracle when it has
// none. A spec violated only because a run that ended at its duration cut an `F` short is a
// time-out or stuck, one violated only by the scenario's start state is start-state
// (VerdictEnding). `file` is the scenario's source, for the atoms' text. A spec
// the trace cannot answer (e.g. a law signal the oracle does not compute) is not judged
// (SpecVerdict::not_judged) and does not keep the others from being judged.
std::vector<SpecVerdict> judge_trace(const ScenarioTemplate& scenario,
                                     std::span<const double> parameters, const Trace& trace,
                                     const RoadMap& map, const SourceFile& file,
                                     const JudgeOptions& options = {});

}  // namespace scenfuzz
