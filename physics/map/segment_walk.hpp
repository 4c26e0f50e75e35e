// Segment look-ups along a polyline that start from a known segment instead of binary-searching
// the whole of it: an actor's arc length moves on by a fraction of a segment per step, so walking
// from the segment found at the last step takes a probe or two where Polyline::segment_at takes
// log2(segments). The answers are exactly Polyline::segment_at's.
#pragma once

#include <algorithm>
#include <cstddef>

#include "physics/map/polyline.hpp"

namespace scenfuzz {

// Polyline::segment_at(s), walking from segment `hint` (any index; the nearer s, the cheaper).
inline std::size_t segment_at_from(const Polyline& path, double s, std::size_t hint) {
  if (s != s) return path.segment_at(s);  // NaN: whatever segment_at makes of it
  const auto& arc = path.arc_lengths();
  const std::size_t last = path.segment_count() - 1;
  std::size_t segment = std::min(hint, last);
  while (segment > 0 && arc[segment] > s) --segment;
  while (segment < last && arc[segment + 1] <= s) ++segment;
  return segment;
}

// The first segment from `segment` on that ends at or beyond arc length `s` (segment_count() when
// none does): the segments before it lie wholly before s. Galloping (1, 2, 4, ... segments on,
// then a binary search in the last stride), as most jumps are short.
inline std::size_t first_segment_reaching(const Polyline& path, std::size_t segment, double s) {
  const auto& arc = path.arc_lengths();
  std::size_t low = segment + 1;  // arc[low - 1] < s is not assumed; arc[low..] is searched
  std::size_t stride = 1;
  while (low + stride < arc.size() && arc[low + stride] < s) {
    low += stride;
    stride *= 2;
  }
  const std::size_t high = std::min(low + stride, arc.size());
  auto end = std::lower_bound(arc.begin() + static_cast<std::ptrdiff_t>(low),
                              arc.begin() + static_cast<std::ptrdiff_t>(high), s);
  return static_cast<std::size_t>(end - arc.begin()) - 1;
}

// first_segment_reaching(path, segment, s), walking from segment `from` (any index; cheap when
// the answer is a few segments from it, as between two looks at a moving point). After `limit`
// steps either way it searches as first_segment_reaching does.
inline std::size_t first_segment_reaching_from(const Polyline& path, std::size_t segment, double s,
                                               std::size_t from, int limit = 8) {
  if (s != s) return first_segment_reaching(path, segment, s);  // NaN: whatever that makes of it
  const auto& arc = path.arc_lengths();
  const std::size_t count = path.segment_count();
  // The answer is the least j from segment on with arc[j + 1] >= s (count when none), or segment
  // itself; arc lengths do not decrease.
  std::size_t first = std::clamp(from, segment, std::max(segment, count));
  for (int step = 0; first > segment && arc[first] >= s; ++step) {
    if (step == limit) return first_segment_reaching(path, segment, s);
    --first;  // segment first - 1 reaches s too
  }
  for (int step = 0; first < count && arc[first + 1] < s; ++step) {
    if (step == limit) return first_segment_reaching(path, segment, s);
    ++first;  // segment first ends before s
  }
  return first;
}

}  // namespace scenfuzz
