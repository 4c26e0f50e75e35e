// The actors' points on a uniform grid, one step at a time (see actor_grid.hpp).
#include "physics/simulation/actor_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scenfuzz {
namespace {

constexpr double kSmallestCell = 25;  // m: about a follower's reach past its path boxes
constexpr double kCellsPerPoint = 2;  // about as many cells as points: building stays cheap

// The index of the cell holding `v` along one axis, clamped to the grid (0 for NaN).
std::size_t index_of(double v, double origin, double cell, std::size_t count) {
  const double at = (v - origin) / cell;
  if (!(at > 0)) return 0;
  // Truncation is the floor here: `at` is positive.
  return at >= static_cast<double>(count - 1) ? count - 1 : static_cast<std::size_t>(at);
}

bool finite(MapPoint p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

std::size_t ActorGrid::column_of(double x) const { return index_of(x, origin_.x, cell_, columns_); }
std::size_t ActorGrid::row_of(double y) const { return index_of(y, origin_.y, cell_, rows_); }

void ActorGrid::build(std::span<const KinematicState> states, std::span<const MapPoint> predicted,
                      std::span<const double> lengths, std::span<const double> widths,
                      std::span<const std::uint8_t> present) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  MapPoint low{kInfinity, kInfinity}, high{-kInfinity, -kInfinity};
  largest_half_extent_ = 0;
  auto filed = [&](std::size_t k) { return present.empty() || present[k] != 0; };
  auto widen = [&](MapPoint p) {
    if (!finite(p)) return;
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  };
  std::size_t point_count = 0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (!filed(k)) continue;
    widen({states[k].x, states[k].y});
    widen(predicted[k]);
    point_count += 2;
    largest_half_extent_ = std::max(largest_half_extent_, lengths[k] / 2 + widths[k] / 2);
  }
  if (!(low.x <= high.x)) low = high = {0, 0};  // nobody (finite) on the map
  // Cells of equal area holding kCellsPerPoint cells per point over the actors' bounding box.
  const double area = (high.x - low.x + kSmallestCell) * (high.y - low.y + kSmallestCell);
  cell_ = std::max(kSmallestCell,
                   std::sqrt(area / (kCellsPerPoint * static_cast<double>(point_count + 1))));
  origin_ = low;
  columns_ = index_of(high.x, low.x, cell_, std::numeric_limits<std::size_t>::max()) + 1;
  rows_ = index_of(high.y, low.y, cell_, std::numeric_limits<std::size_t>::max()) + 1;
  filed_.clear();
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (!filed(k)) continue;
    const auto actor = static_cast<std::uint32_t>(k);
    const MapPoint points[] = {{states[k].x, states[k].y}, predicted[k]};
    std::size_t last = std::numeric_limits<std::size_t>::max();
    for (const MapPoint& p : points) {
      if (!finite(p)) continue;
      const std::size_t cell = row_of(p.y) * columns_ + column_of(p.x);
      if (cell != last) filed_.push_back({cell, actor});
      last = cell;
    }
  }
  // A counting sort by cell; actors come in ascending order, so each cell's list is ascending.
  starts_.assign(columns_ * rows_ + 1, 0);
  for (const auto& [cell, actor] : filed_) ++starts_[cell + 1];
  for (std::size_t c = 0; c + 1 < starts_.size(); ++c) starts_[c + 1] += starts_[c];
  actors_.resize(filed_.size());
  std::vector<std::uint32_t>& next = scratch_;
  next.assign(starts_.begin(), starts_.end() - 1);
  for (const auto& [cell, actor] : filed_) actors_[next[cell]++] = actor;
}

void ActorGrid::near(MapPoint low, MapPoint high, std::vector<std::uint32_t>& actors) const {
  actors.clear();
  if (columns_ == 0) return;
  const std::size_t column_low = column_of(low.x), column_high = column_of(high.x);
  const std::size_t row_low = row_of(low.y), row_high = row_of(high.y);
  for (std::size_t row = row_low; row <= row_high; ++row) {
    const std::size_t first = row * columns_;
    actors.insert(actors.end(), actors_.begin() + starts_[first + column_low],
                  actors_.begin() + starts_[first + column_high + 1]);
  }
  std::sort(actors.begin(), actors.end());
  actors.erase(std::unique(actors.begin(), actors.end()), actors.end());
}

}  // namespace scenfuzz
