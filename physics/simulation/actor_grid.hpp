// A uniform grid over the actors' points at one step (where each is and where it is predicted to
// be, predicted_points.hpp), so that a lane follower's scan looks only at the actors near its
// path ahead instead of at every actor: built once per step by the simulation for all followers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

class ActorGrid {
 public:
  // Files every actor k with present[k] != 0 (every actor when `present` is empty) under the
  // cells of its position and of predicted[k]; `lengths` and `widths` are the bodies' (by actor).
  void build(std::span<const KinematicState> states, std::span<const MapPoint> predicted,
             std::span<const double> lengths, std::span<const double> widths,
             std::span<const std::uint8_t> present);

  // The largest half length plus half width of a filed actor's body (m): how far its body can
  // reach out from its point, whichever way it is turned.
  double largest_half_extent() const { return largest_half_extent_; }

  // Every filed actor with a point (finite) in the rectangle [low, high], and possibly some near
  // it, into `actors`: ascending, each once.
  void near(MapPoint low, MapPoint high, std::vector<std::uint32_t>& actors) const;

 private:
  std::size_t column_of(double x) const;
  std::size_t row_of(double y) const;

  double cell_ = 1;
  MapPoint origin_{0, 0};
  std::size_t columns_ = 0, rows_ = 0;
  std::vector<std::uint32_t> starts_;  // actors_[starts_[c] .. starts_[c + 1]) are in cell c
  std::vector<std::uint32_t> actors_;  // by cell (row-major), ascending within a cell
  std::vector<std::pair<std::size_t, std::uint32_t>> filed_;  // (cell, actor), for building
  std::vector<std::uint32_t> scratch_;                        // for building
  double largest_half_extent_ = 0;
};

}  // namespace scenfuzz
