// Sweep-and-prune: insertion sort on the low x (nearly sorted from the last step), then one
// sweep that pairs each body with the following ones until their low x passes its high x.
#include "physics/collision/body_sweep.hpp"

#include <algorithm>

#include "lang/demand.hpp"

namespace scenfuzz {

std::uint32_t BodySweep::add(const SweepBox& box, bool is_static) {
  const auto id = static_cast<std::uint32_t>(boxes_.size());
  boxes_.push_back(box);
  is_static_.push_back(is_static ? 1 : 0);
  enabled_.push_back(1);
  order_.push_back(id);
  return id;
}

void BodySweep::move(std::uint32_t body, const SweepBox& box) {
  SCENFUZZ_DEMAND(body < boxes_.size() && "no such body");
  boxes_[body] = box;
}

void BodySweep::set_enabled(std::uint32_t body, bool enabled) {
  SCENFUZZ_DEMAND(body < boxes_.size() && "no such body");
  enabled_[body] = enabled ? 1 : 0;
}

void BodySweep::sort_by_low_x() {
  for (std::size_t i = 1; i < order_.size(); ++i) {
    const std::uint32_t id = order_[i];
    const double key = boxes_[id].min_x;
    std::size_t j = i;
    for (; j > 0 && boxes_[order_[j - 1]].min_x > key; --j) order_[j] = order_[j - 1];
    order_[j] = id;
  }
}

void BodySweep::overlapping_pairs(std::vector<Pair>& pairs) {
  pairs.clear();
  sort_by_low_x();
  for (std::size_t i = 0; i < order_.size(); ++i) {
    const std::uint32_t a = order_[i];
    if (!enabled_[a]) continue;
    const SweepBox& box_a = boxes_[a];
    // Every later body starts at or after a's low x, so its x range overlaps a's exactly when it
    // starts at or before a's high x.
    for (std::size_t j = i + 1; j < order_.size(); ++j) {
      const std::uint32_t b = order_[j];
      const SweepBox& box_b = boxes_[b];
      if (box_b.min_x > box_a.max_x) break;
      if ((is_static_[a] && is_static_[b]) || !enabled_[b]) continue;
      if (box_a.min_y <= box_b.max_y && box_b.min_y <= box_a.max_y)
        pairs.push_back(std::minmax(a, b));
    }
  }
}

}  // namespace scenfuzz
