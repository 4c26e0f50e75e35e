// Bounding boxes of runs of polyline segments (see polyline_boxes.hpp).
#include "physics/map/polyline_boxes.hpp"

#include <algorithm>

namespace scenfuzz {
namespace {

// m added to a reach before comparing: far above the rounding of a distance between map points
// (about 1e-9 m at UTM coordinates), far below anything that matters.
constexpr double kRoundingMargin = 1e-6;

}  // namespace

PolylineBoxes::PolylineBoxes(const Polyline& path) {
  const auto& points = path.points();
  for (std::size_t start = 0; start < path.segment_count(); start += kRun) {
    const std::size_t end = std::min(start + kRun, path.segment_count());  // last vertex
    Box box{points[start], points[start]};
    for (std::size_t i = start + 1; i <= end; ++i) {
      box.low = {std::min(box.low.x, points[i].x), std::min(box.low.y, points[i].y)};
      box.high = {std::max(box.high.x, points[i].x), std::max(box.high.y, points[i].y)};
    }
    boxes_.push_back(box);
  }
}

bool PolylineBoxes::all_beyond(const Polyline& path, MapPoint point, std::size_t first,
                               double until, double reach) const {
  const auto& arc = path.arc_lengths();
  const double limit = (reach + kRoundingMargin) * (reach + kRoundingMargin);
  for (std::size_t k = first / kRun; k < boxes_.size() && arc[k * kRun] <= until; ++k) {
    const Box& box = boxes_[k];
    const double dx = std::max({box.low.x - point.x, 0.0, point.x - box.high.x});
    const double dy = std::max({box.low.y - point.y, 0.0, point.y - box.high.y});
    if (dx * dx + dy * dy <= limit) return false;
  }
  return true;
}

}  // namespace scenfuzz
