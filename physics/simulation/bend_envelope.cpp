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

std::vector<double> bend_envelope(const Polyline& path, LazyHeadings& headings,
                                  double lateral_acceleration, double deceleration,
                                  double max_speed) {
  const std::size_t count = path.points().size();
  // A turn below 2 blend lateral / max_speed^2 at a vertex caps the speed above max_speed
  // (curvature = turn / (2 blend), cap = sqrt(lateral / curvature)); counting it or not changes
  // no envelope value below max_speed (each is the least of the caps ahead, grown by braking
  // distance, and growing is monotonic). 98 % of it is the limit: a cap 1 % above max_speed,
  // far beyond rounding.
  const double per_blend = lateral_acceleration > 0 && max_speed > 0
                               ? lateral_acceleration / (max_speed * max_speed)
                               : 0;
  std::vector<double> envelope(count, kInfinity);
  for (std::size_t i = count; i-- > 0;) {
    double cap = kInfinity;
    if (i > 0 && i + 1 < count) {
      const double limit = std::min(0.98 * 2 * blend_half_width(path, i) * per_blend, 0.1);
      if (!surely_slighter(path, i, limit)) {
        ensure_headings(headings, path, i - 1, i);
        double curvature = vertex_curvature(path, headings.values, i);
        cap = curvature > 1e-9 ? std::sqrt(lateral_acceleration / curvature) : kInfinity;
      }
    }
    if (i + 1 < count) {
      double ds = path.arc_lengths()[i + 1] - path.arc_lengths()[i];
      cap = std::min(cap, std::sqrt(envelope[i + 1] * envelope[i + 1] + 2 * deceleration * ds));
    }
    envelope[i] = cap;
  }
  return envelope;
}

}  // namespace scenfuzz
