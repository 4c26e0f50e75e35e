// Judging a run: every spec of the scenario evaluated on its trace, or, when the scenario has no
// spec, the collision oracle. What the search minimises and what `scenfuzz run` reports.
#pragma once

#include <span>
#include <string>
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

struct SpecVerdict {
  std::string name;       // the spec's name, or kNoCollisionSpec
  double robustness = 0;  // at t = 0; +inf/-inf possible
  double time = 0;        // when the responsible atom has that value (the collision oracle: when
                          // the ego is nearest to another body)
  SourceLocation atom;    // the responsible atom in the file; unknown for the collision oracle
                          // and for an infinity no atom gives
  std::string atom_text;  // that atom as written, or for the collision oracle which bodies
  // What a search minimises: the robustness, or for a conjunction the conjunct guide
  // (search_guide.hpp); negative exactly when the robustness is.
  double guide = 0;

  bool violated() const { return robustness < 0; }
};

// How the collision oracle treats collisions that are not the ego's fault (oracle/responsibility).
struct JudgeOptions {
  RssParameters rss;
  bool all_collisions = false;  // --all-collisions: count them too
};

// One verdict per spec of `scenario`, in file order, or one from the collision oracle when it has
// none. `file` is the scenario's source, for the atoms' text. Throws OracleError for a spec the
// trace cannot answer (e.g. a law signal the oracle does not compute).
std::vector<SpecVerdict> judge_trace(const ScenarioTemplate& scenario,
                                     std::span<const double> parameters, const Trace& trace,
                                     const RoadMap& map, const SourceFile& file,
                                     const JudgeOptions& options = {});

}  // namespace scenfuzz
