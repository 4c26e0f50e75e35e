// Bounding boxes of runs of polyline segments (see polyline_boxes.hpp).
#include "physics/map/polyline_boxes.hpp"

namespace scenfuzz {

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
  for (std::size_t start = 0; start < boxes_.size(); start += kGroup) {
    Box group = boxes_[start];
    for (std::size_t k = start + 1; k < std::min(start + kGroup, boxes_.size()); ++k) {
      group.low = {std::min(group.low.x, boxes_[k].low.x), std::min(group.low.y, boxes_[k].low.y)};
      group.high = {std::max(group.high.x, boxes_[k].high.x),
                    std::max(group.high.y, boxes_[k].high.y)};
    }
    groups_.push_back(group);
  }
}

}  // namespace scenfuzz
