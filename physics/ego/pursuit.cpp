// Pure pursuit (pursuit.hpp).
#include "physics/ego/pursuit.hpp"

#include <cmath>

#include "physics/map/point_at_from.hpp"

namespace scenfuzz {

double pursuit_steering(const RouteTracker& route, const OvertakePlan& plan, double progress,
                        const KinematicState& ego, const ActorClass& vehicle, double lookahead) {
  if (route.empty()) return 0;
  double half_base = vehicle.wheelbase / 2;
  MapPoint rear{ego.x - half_base * std::cos(ego.heading),
                ego.y - half_base * std::sin(ego.heading)};
  double target_s = progress + lookahead;
  MapPoint target;
  if (target_s <= route.length()) {
    // Overtaking moves the aim sideways, as the plan has it at the target point.
    const std::size_t segment = route.segment_at(target_s);  // once, for the point and heading
    target = point_at_from(route.path(), target_s, segment);
    double offset = planned_lateral(plan, target_s);
    double heading = route.heading_at(target_s, segment);
    target = {target.x - offset * std::sin(heading), target.y + offset * std::cos(heading)};
  } else {
    // Beyond the end, keep aiming along the path's last direction.
    MapPoint end = route.path().point_at(route.length());
    double heading = route.heading_at(route.length());
    double beyond = target_s - route.length();
    target = {end.x + beyond * std::cos(heading), end.y + beyond * std::sin(heading)};
  }
  double dx = target.x - rear.x, dy = target.y - rear.y;
  double reach = std::hypot(dx, dy);
  if (reach < 1e-6) return 0;
  double alpha = angle_difference(std::atan2(dy, dx), ego.heading);
  return std::atan(2 * vehicle.wheelbase * std::sin(alpha) / reach);
}

}  // namespace scenfuzz
