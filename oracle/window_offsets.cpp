// Constant window offsets, proposed at the middle sample and checked at every sample with a few
// comparisons per sample that the compiler vectorises (window_offsets.hpp).
#include "oracle/window_offsets.hpp"

#include <algorithm>

#include "oracle/robustness.hpp"

namespace scenfuzz {

namespace {

// The edges the definition gives sample i, tested at the proposed [begin, end): since times
// increase, t_j - t_i (rounded) never decreases in j, so the window's first sample is `begin`
// exactly when it is in reach of `lower` and the sample before it is not, and likewise its end.
// (The WindowCursor walk in robustness.cpp, for other windows, finds the same edges.)
bool edges_hold(std::span<const double> time, std::size_t i, std::size_t begin, std::size_t end,
                double lower, double upper) {
  const std::size_t n = time.size();
  const double t = time[i];
  return (begin == n || time[begin] - t >= lower) && (begin == 0 || time[begin - 1] - t < lower) &&
         (end == n || time[end] - t > upper) && (end == 0 || time[end - 1] - t <= upper);
}

// edges_hold for samples [from, to) whose proposed edges lie inside the trace with a sample on
// either side: no clipping and no branches, so the loop vectorises.
bool inner_edges_hold(std::span<const double> time, std::ptrdiff_t from, std::ptrdiff_t to,
                      Offsets offsets, double lower, double upper) {
  const double* t = time.data();
  bool wrong = false;
  for (std::ptrdiff_t i = from; i < to; ++i) {
    const double begin_gap = t[i + offsets.first] - t[i];
    const double before_gap = t[i + offsets.first - 1] - t[i];
    const double end_gap = t[i + offsets.last + 1] - t[i];
    const double last_gap = t[i + offsets.last] - t[i];
    wrong |= (begin_gap < lower) | (before_gap >= lower) | (end_gap <= upper) | (last_gap > upper);
  }
  return !wrong;
}

}  // namespace

std::optional<Offsets> constant_window_offsets(std::span<const double> time,
                                               const TimeInterval& interval) {
  const auto n = static_cast<std::ptrdiff_t>(time.size());
  if (n == 0) return std::nullopt;
  const double lower = interval.lower - kWindowTolerance, upper = interval.upper + kWindowTolerance;
  // The middle sample's window, found by bisection, proposes the offsets.
  const std::ptrdiff_t middle = n / 2;
  const double t = time[static_cast<std::size_t>(middle)];
  const auto first =
      std::partition_point(time.begin(), time.end(), [&](double tj) { return tj - t < lower; });
  const auto last =
      std::partition_point(first, time.end(), [&](double tj) { return tj - t <= upper; });
  const Offsets offsets{(first - time.begin()) - middle, (last - time.begin()) - middle - 1};
  // Samples [inner_from, inner_to) have both proposed edges strictly inside the trace.
  const std::ptrdiff_t inner_from = std::clamp<std::ptrdiff_t>(1 - offsets.first, 0, n);
  const std::ptrdiff_t inner_to = std::clamp<std::ptrdiff_t>(n - 1 - offsets.last, inner_from, n);
  if (!inner_edges_hold(time, inner_from, inner_to, offsets, lower, upper)) return std::nullopt;
  auto clipped = [n](std::ptrdiff_t index) {
    return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(index, 0, n));
  };
  auto outer_holds = [&](std::ptrdiff_t i) {
    return edges_hold(time, static_cast<std::size_t>(i), clipped(i + offsets.first),
                      clipped(i + offsets.last + 1), lower, upper);
  };
  for (std::ptrdiff_t i = 0; i < inner_from; ++i)
    if (!outer_holds(i)) return std::nullopt;
  for (std::ptrdiff_t i = inner_to; i < n; ++i)
    if (!outer_holds(i)) return std::nullopt;
  return offsets;
}

}  // namespace scenfuzz
