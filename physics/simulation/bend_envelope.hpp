// A lane follower's speed envelope for the bends of its path, and the path's segment headings,
// both computed only where they are needed: a follower's path is mostly straight, and it drives
// only part of it in a run, so an atan2 for each of its segments at setup was most of the setup's
// cost.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "lang/demand.hpp"
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
// it matters to a body that is never faster than `speed_bound`: min(at(i), speed_bound) is bit for
// bit that of the envelope with every vertex's bend counted over the whole path.
//
// Made as far along the path as it is read (extend): a follower's path is laid for the scenario's
// whole duration, and a run that ends sooner (a 30 s benchmark of a 120 s scenario, a search that
// stops at a collision) reads only the start of it. A bend ahead lowers the envelope only within
// reach(), the distance in which braking from speed_bound comes to its cap, so a backward pass
// begun that far beyond a vertex gives its final value. Values at or above speed_bound are kept as
// infinity (they are all alike to such a body), so a straight stretch costs no square root, and a
// vertex whose turn is surely too slight to cap the speed below speed_bound is not counted (a cross
// product, no headings); the others' headings are computed into the follower's LazyHeadings.
class BendEnvelope {
 public:
  BendEnvelope() = default;
  BendEnvelope(const Polyline& path, double lateral_acceleration, double deceleration,
               double speed_bound);

  double speed_bound() const { return speed_bound_; }
  // m beyond a vertex whose bends can lower its value below speed_bound.
  double reach() const { return reach_; }
  // Vertices 0 .. final_count() - 1 have their final values.
  std::size_t final_count() const { return final_; }

  // Makes vertices 0 .. vertex final (clamped to the path).
  void extend(const Polyline& path, LazyHeadings& headings, std::size_t vertex);
  // Raises the speed bound (for a body found faster than it), recomputing what was final.
  void raise_bound(const Polyline& path, LazyHeadings& headings, double speed_bound);

  double at(std::size_t vertex) const {
    SCENFUZZ_DEMAND(vertex < final_);
    return values_[vertex];
  }

 private:
  void set_bound(double speed_bound);
  double cap_at(const Polyline& path, LazyHeadings& headings, std::size_t vertex) const;

  std::vector<double> values_;  // infinity where not computed
  std::size_t final_ = 0;
  double lateral_ = 0, deceleration_ = 0, speed_bound_ = 0, reach_ = 0;
  double per_blend_ = 0;  // lateral / speed_bound^2: the skip test's turn per blend width
};

}  // namespace scenfuzz
