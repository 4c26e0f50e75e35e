// How many seconds of trace a spec needs to be decided: its time horizon. `F[0:40] p` reads 40 s
// past the start; nested operators add up (`G[0:10] F[0:5] p` reads 15 s), an until reads as far
// as its interval's end plus the farther of its operands. An operator over the rest of the trace
// (`F p`, `G p`, `p U q` without an interval) reads whatever trace there is and asks for no
// particular length, so it adds nothing; X reads one more sample, less than any duration a user
// writes, and adds nothing either. Past-looking windows (`F[-3:0]`) add nothing.
//
// The default duration (physics/simulation/default_duration.hpp) is at least the longest horizon
// of a scenario's specs, and a shorter duration given on the command line or in the file is
// warned about.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lang/spec.hpp"

namespace scenfuzz {

// Seconds after the current sample that `formula` reads; 0 when it reads no future sample.
double formula_horizon(const Formula& formula);

struct SpecHorizon {
  std::string spec;  // the spec's name
  double seconds = 0;
};

// The spec with the longest horizon (the first of equals); nullopt when there is no spec or none
// reads any time ahead.
std::optional<SpecHorizon> longest_horizon(std::span<const Spec> specs);

// The specs whose horizon is longer than `duration` seconds, in file order.
std::vector<SpecHorizon> horizons_beyond(std::span<const Spec> specs, double duration);

}  // namespace scenfuzz
