// Bounding boxes of runs of polyline segments (see polyline_boxes.hpp).
#include "physics/map/polyline_boxes.hpp"

#include "lang/demand.hpp"

namespace scenfuzz {

PolylineBoxes::PolylineBoxes(const Polyline& path) { extend(path, path.segment_count()); }

void PolylineBoxes::extend(const Polyline& path, std::size_t segments) {
  const std::size_t count = path.segment_count();
  SCENFUZZ_DEMAND(segments == count || (segments < count && segments % (kRun * kGroup) == 0));
  if (segments <= segments_) return;
  const auto& points = path.points();
  for (std::size_t start = segments_; start < segments; start += kRun) {
    const std::size_t end = std::min(start + kRun, count);  // last vertex
    Box box{points[start], points[start]};
    for (std::size_t i = start + 1; i <= end; ++i) {
      box.low = {std::min(box.low.x, points[i].x), std::min(box.low.y, points[i].y)};
      box.high = {std::max(box.high.x, points[i].x), std::max(box.high.y, points[i].y)};
    }
    boxes_.push_back(box);
  }
  for (std::size_t start = groups_.size() * kGroup; start < boxes_.size(); start += kGroup) {
    Box group = boxes_[start];
    for (std::size_t k = start + 1; k < std::min(start + kGroup, boxes_.size()); ++k) {
      group.low = {std::min(group.low.x, boxes_[k].low.x), std::min(group.low.y, boxes_[k].low.y)};
      group.high = {std::max(group.high.x, boxes_[k].high.x),
                    std::max(group.high.y, boxes_[k].high.y)};
    }
    groups_.push_back(group);
  }
  segments_ = segments;
}

}  // namespace scenfuzz
