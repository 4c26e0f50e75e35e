// Constant window offsets, proposed at the middle sample and checked at every sample with a few
// comparisons per sample that the compiler vectorises (window_offsets.hpp).
#include "oracle/window_offsets.hpp"

#include <algorithm>
#include <limits>

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
// either side, as the extremes of the four gaps: no clipping and no branches, and blocks of a fixed
// count of samples, which the compiler vectorises at -O2.
bool inner_edges_hold(std::span<const double> time, std::ptrdiff_t from, std::ptrdiff_t to,
                      Offsets offsets, double lower, double upper) {
  constexpr std::ptrdiff_t kBlock = 4;
  const double* t = time.data();
  const double* begin = t + offsets.first;
  const double* end = t + offsets.last + 1;
  double least_begin[kBlock], most_before[kBlock], most_last[kBlock], least_end[kBlock];
  for (std::ptrdiff_t k = 0; k < kBlock; ++k) {
    least_begin[k] = least_end[k] = std::numeric_limits<double>::infinity();
    most_before[k] = most_last[k] = -std::numeric_limits<double>::infinity();
  }
  auto take = [&](std::ptrdiff_t k, std::ptrdiff_t i) {
    least_begin[k] = std::min(least_begin[k], begin[i] - t[i]);
    most_before[k] = std::max(most_before[k], begin[i - 1] - t[i]);
    most_last[k] = std::max(most_last[k], end[i - 1] - t[i]);
    least_end[k] = std::min(least_end[k], end[i] - t[i]);
  };
  std::ptrdiff_t i = from;
  for (; i + kBlock <= to; i += kBlock)
    for (std::ptrdiff_t k = 0; k < kBlock; ++k) take(k, i + k);
  for (; i < to; ++i) take(0, i);
  bool hold = true;
  for (std::ptrdiff_t k = 0; k < kBlock; ++k)
    hold = hold && least_begin[k] >= lower && most_before[k] < lower && most_last[k] <= upper &&
           least_end[k] > upper;
  return hold;
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
