// The bend envelope of a follower's path, skipping the slight bends (see bend_envelope.hpp).
#include "physics/simulation/bend_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/actors/path_pose.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Whether the turn at `vertex` is surely less than `limit` radians (which is at most 0.1). With u
// and w the adjoining segments' directions, a turn below pi/2 has sin(turn) = |u x w| / |u||w|;
// sin(x) >= 0.99 x for x <= 0.1, so |u x w| < 0.99 limit |u||w| means turn < limit, with a margin
// far beyond rounding (the turn vertex_curvature computes from the two atan2s is within 1e-15).
bool surely_slighter(const Polyline& path, std::size_t vertex, double limit) {
  const MapPoint& a = path.points()[vertex - 1];
  const MapPoint& b = path.points()[vertex];
  const MapPoint& c = path.points()[vertex + 1];
  const double ux = b.x - a.x, uy = b.y - a.y, wx = c.x - b.x, wy = c.y - b.y;
  const double dot = ux * wx + uy * wy;
  if (!(dot > 0)) return false;
  const double cross = ux * wy - uy * wx;
  const double bound = 0.99 * limit;
  return cross * cross < bound * bound * ((ux * ux + uy * uy) * (wx * wx + wy * wy));
}

}  // namespace

LazyHeadings lazy_headings(const Polyline& path) {
  return {std::vector<double>(path.segment_count(), std::nan(""))};
}

double compute_heading(LazyHeadings& headings, const Polyline& path, std::size_t k) {
  const MapPoint& a = path.points()[k];
  const MapPoint& b = path.points()[k + 1];
  return headings.values[k] = std::atan2(b.y - a.y, b.x - a.x);
}

BendEnvelope::BendEnvelope(const Polyline& path, double lateral_acceleration, double deceleration,
                           double speed_bound)
    : values_(path.points().size(), kInfinity),
      lateral_(lateral_acceleration),
      deceleration_(deceleration) {
  set_bound(speed_bound);
}

void BendEnvelope::set_bound(double speed_bound) {
  speed_bound_ = speed_bound;
  // A cap c at distance D ahead lowers a value to sqrt(c^2 + 2 deceleration D) at least: at or
  // above speed_bound from speed_bound^2 / (2 deceleration) on; 1 % more is far beyond the
  // rounding of the pass's chain of roots.
  reach_ =
      deceleration_ > 0 ? 1.01 * speed_bound * speed_bound / (2 * deceleration_) + 1e-3 : kInfinity;
  // A turn below 2 blend lateral / speed_bound^2 at a vertex caps the speed above speed_bound
  // (curvature = turn / (2 blend), cap = sqrt(lateral / curvature)). 98 % of it is the skip
  // test's limit: a cap 1 % above speed_bound, far beyond rounding.
  per_blend_ = lateral_ > 0 && speed_bound > 0 ? lateral_ / (speed_bound * speed_bound) : 0;
}

double BendEnvelope::cap_at(const Polyline& path, LazyHeadings& headings,
                            std::size_t vertex) const {
  if (vertex == 0 || vertex + 1 >= path.points().size()) return kInfinity;
  const double limit = std::min(0.98 * 2 * blend_half_width(path, vertex) * per_blend_, 0.1);
  if (surely_slighter(path, vertex, limit)) return kInfinity;
  ensure_headings(headings, path, vertex - 1, vertex);
  const double curvature = vertex_curvature(path, headings.values, vertex);
  return curvature > 1e-9 ? std::sqrt(lateral_ / curvature) : kInfinity;
}

void BendEnvelope::extend(const Polyline& path, LazyHeadings& headings, std::size_t vertex) {
  const std::size_t count = values_.size();
  vertex = std::min(vertex, count - 1);
  if (vertex < final_) return;
  const auto& arc = path.arc_lengths();
  // The pass starts reach_ beyond the vertex (or at the path's end), as if nothing lay beyond.
  std::size_t end = vertex;
  while (end + 1 < count && arc[end] < arc[vertex] + reach_) ++end;
  for (std::size_t i = end + 1; i-- > final_;) {
    double value = cap_at(path, headings, i);
    if (i < end && values_[i + 1] != kInfinity) {
      const double ds = arc[i + 1] - arc[i];
      value = std::min(value, std::sqrt(values_[i + 1] * values_[i + 1] + 2 * deceleration_ * ds));
    }
    values_[i] = value >= speed_bound_ ? kInfinity : value;
  }
  final_ =
      end + 1 == count
          ? count
          : static_cast<std::size_t>(
                std::upper_bound(arc.begin(), arc.begin() + end, arc[end] - reach_) - arc.begin());
  SCENFUZZ_DEMAND(final_ > vertex);
}

void BendEnvelope::raise_bound(const Polyline& path, LazyHeadings& headings, double speed_bound) {
  const std::size_t needed = final_;
  set_bound(speed_bound);
  std::fill(values_.begin(), values_.end(), kInfinity);
  final_ = 0;
  if (needed > 0) extend(path, headings, needed - 1);
}

}  // namespace scenfuzz
