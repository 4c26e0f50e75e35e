// Constant window offsets: on a uniformly sampled trace every sample's window [a, b] is the same
// run of samples shifted, [i + first, i + last], which lets G, F and U over it run van Herk /
// Gil-Werman instead of the two-stack sliding window. Found only when they are exactly the windows
// the definition gives (a <= t_j - t_i <= b up to kWindowTolerance) at every sample.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "lang/spec.hpp"

namespace scenfuzz {

// Sample i's window is [i + first, i + last] clipped to the trace (empty when last < first).
struct Offsets {
  std::ptrdiff_t first = 0, last = -1;
};

// The interval's windows over `time` (strictly increasing) as constant offsets, or nullopt when
// they are not (uneven sampling, rounding that moves a window edge past a sample, an empty trace).
std::optional<Offsets> constant_window_offsets(std::span<const double> time,
                                               const TimeInterval& interval);

}  // namespace scenfuzz
