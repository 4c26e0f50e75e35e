// `scenfuzz tmin` on a file: reads a finding the search wrote (its header's replay command gives
// the seed and the simulation options, its "failure mode:" line the mode) or a plain concrete
// scenario (seed 0, default options, the failure `run` judges), replays it as the search judges,
// reduces it (fuzz/tmin.hpp) while the same failure-mode signature persists, checks that the
// result replays to that mode and writes it atomically as canonical AVUnit with a header of what
// changed and the replay command (WMG SDL findings as WMG SDL level 2, fuzz/tmin_wmg.hpp). The
// search's and campaigns' `--tmin` call minimize_finding.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace scenfuzz {

struct TminOptions {
  std::string out_path;  // empty: beside the input, <stem>.min.avu (.min.sdl for WMG SDL)
  // Asked before every replay: true stops the reduction, and nothing is written (the result's
  // `interrupted` says so). Empty: never stops.
  std::function<bool()> interrupted;
};

struct TminResult {
  std::string error;  // why nothing was written (bad input, no failure on replay); empty: written
  std::string out_path;
  std::string mode;    // the failure-mode signature kept
  std::string replay;  // the output's replay command
  std::vector<std::string> changes;
  std::size_t actors_before = 0, actors_removed = 0;
  std::size_t waypoints_removed = 0, obstacles_removed = 0;
  std::size_t digits_before = 0, digits_after = 0;
  std::size_t replays = 0;   // simulations the reduction ran
  bool interrupted = false;  // a stop came first (TminOptions::interrupted); error says so

  bool ok() const { return error.empty(); }
};

// Where tmin writes by default: beside the input, <stem>.min.avu (.min.sdl for WMG SDL).
std::string default_minimised_path(const std::string& input);

// Reduces the scenario in `finding_path`; the result says what was written, or why nothing was.
// Deterministic: the same input and options give the same output, byte for byte.
TminResult minimize_finding(const std::string& finding_path, const TminOptions& options);

}  // namespace scenfuzz
