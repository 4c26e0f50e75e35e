// A lane follower's speed envelope for the bends of its path, and the path's segment headings
// computed only where they are needed: a follower's path is mostly straight, and it drives only
// part of it in a run, so an atan2 for each of its segments at setup was most of the setup's cost.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "physics/map/polyline.hpp"

namespace scenfuzz {

// Each path segment's heading (the atan2 of its direction, as segment_headings), computed on
// first use: NaN until then.
struct LazyHeadings {
  std::vector<double> values;
};

LazyHeadings lazy_headings(const Polyline& path);
// Computes segment k's heading into `headings` and returns it.
double compute_heading(LazyHeadings& headings, const Polyline& path, std::size_t k);

// Segment k's heading, computing it when it has not been (inline: a follower asks at every step).
inline double heading_of(LazyHeadings& headings, const Polyline& path, std::size_t k) {
  const double value = headings.values[k];
  return std::isnan(value) ? compute_heading(headings, path, k) : value;
}

// Computes the headings of segments first..last (clamped to the path) that are not yet known.
inline void ensure_headings(LazyHeadings& headings, const Polyline& path, std::size_t first,
                            std::size_t last) {
  const std::size_t end = std::min(last + 1, headings.values.size());
  for (std::size_t k = first; k < end; ++k) heading_of(headings, path, k);
}

// At each vertex, the most speed from which every bend ahead can still be taken within
// `lateral_acceleration`, braking at `deceleration` (a backward pass over the vertices), as far as
// it matters to a body that is never faster than `max_speed`: min(envelope[i], max_speed) is
// bit for bit that of the envelope with every vertex's bend counted. A vertex whose turn is surely
// too slight to cap the speed below max_speed is not counted (a cross product, no headings);
// the others' headings are computed into `headings`.
std::vector<double> bend_envelope(const Polyline& path, LazyHeadings& headings,
                                  double lateral_acceleration, double deceleration,
                                  double max_speed);

}  // namespace scenfuzz
