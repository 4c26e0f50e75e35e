#include "physics/simulation/observed_manoeuvre.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>

#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

ObservedManoeuvre observe_manoeuvre(const RoadMap& map, const KinematicState& state, LaneFix lane) {
  if (state.speed < kStoppedSpeed) return ObservedManoeuvre::stopped;
  if (state.reversing) return ObservedManoeuvre::reverse;
  if (lane.lane < 0) return ObservedManoeuvre::going_ahead;
  const Lane& on = map.lane(static_cast<LaneIndex>(lane.lane));
  const double relative = angle_difference(
      state.heading, lane_heading_at(map, static_cast<LaneIndex>(lane.lane), lane.s));
  if (std::cos(relative) < 0) return ObservedManoeuvre::reverse;
  if (on.junction && on.turn == LaneTurn::left) return ObservedManoeuvre::turn_left;
  if (on.junction && on.turn == LaneTurn::right) return ObservedManoeuvre::turn_right;
  const double lateral_speed = state.speed * std::sin(relative);
  if (lateral_speed > kLaneChangeLateralSpeed) return ObservedManoeuvre::lane_change_left;
  if (lateral_speed < -kLaneChangeLateralSpeed) return ObservedManoeuvre::lane_change_right;
  return ObservedManoeuvre::going_ahead;
}

std::optional<ObservedManoeuvre> observed_manoeuvre_named(std::string_view word) {
  std::string key;
  for (char c : word)
    if (std::isalnum(static_cast<unsigned char>(c)))
      key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  static const std::array<std::pair<std::string_view, ObservedManoeuvre>, 7> names{{
      {"goingahead", ObservedManoeuvre::going_ahead},
      {"stopped", ObservedManoeuvre::stopped},
      {"lanechangeleft", ObservedManoeuvre::lane_change_left},
      {"lanechangeright", ObservedManoeuvre::lane_change_right},
      {"turnleft", ObservedManoeuvre::turn_left},
      {"turnright", ObservedManoeuvre::turn_right},
      {"reverse", ObservedManoeuvre::reverse},
  }};
  for (const auto& [name, manoeuvre] : names)
    if (key == name) return manoeuvre;
  return std::nullopt;
}

}  // namespace scenfuzz
