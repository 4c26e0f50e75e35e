// The collision world's broadphase: sweep-and-prune over the bodies' axis-aligned footprint
// bounds. The bodies stay sorted by the low x of their bounds between steps; as they move a
// little each step, re-sorting by insertion is nearly linear, and the sweep then tests only the
// pairs whose x ranges overlap, instead of every pair (FCL's brute-force manager, quadratic in
// the bodies). Pure geometry, no FCL: it stays cheap to include and to test.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace scenfuzz {

// Closed bounds: boxes that share only an edge overlap.
struct SweepBox {
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
};

inline bool boxes_overlap(const SweepBox& a, const SweepBox& b) {
  return a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y && b.min_y <= a.max_y;
}

class BodySweep {
 public:
  using Pair = std::pair<std::uint32_t, std::uint32_t>;

  // Ids are dense from 0 in the order bodies are added. Static bodies never pair with each
  // other.
  std::uint32_t add(const SweepBox& box, bool is_static);
  void move(std::uint32_t body, const SweepBox& box);
  // A disabled body pairs with nothing (a background-traffic vehicle not yet on the map, or gone
  // from it); bodies are enabled when added.
  void set_enabled(std::uint32_t body, bool enabled);

  // Replaces `pairs` with every pair of overlapping boxes, except static-static ones, each once
  // as (lower id, higher id), in no particular order.
  void overlapping_pairs(std::vector<Pair>& pairs);

 private:
  void sort_by_low_x();

  std::vector<SweepBox> boxes_;
  std::vector<std::uint8_t> is_static_;
  std::vector<std::uint8_t> enabled_;
  std::vector<std::uint32_t> order_;  // body ids by boxes_[id].min_x
};

}  // namespace scenfuzz
