// Where a stop event aims (stop_place.hpp says the rule).
#include "lang/accident/stop_place.hpp"

#include <cmath>
#include <string>

#include "lang/accident/way_in.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::accident {

namespace {

constexpr double kRoadside = 5;  // m beyond the carriageway's edge a sign may stand

// Whether the event keeps the speed the vehicle started with and its way in (a lane change
// moves across it, not along it).
bool keeps_speed_and_way(const Event& event, std::size_t k) {
  switch (event.kind.value) {
    case EventKind::driving_forward: return k == 0;  // a later one has a speed of its own
    case EventKind::change_lane_left:
    case EventKind::change_lane_right: return true;
    default: return false;
  }
}

}  // namespace

std::optional<StopAim> stop_aim(const File& file, const SceneLayout& layout, const Vehicle& vehicle,
                                Direction heading, Diagnostics& diagnostics) {
  if (!vehicle.end_sign) return std::nullopt;
  std::size_t stop = 0;
  while (stop < vehicle.chain.size() && vehicle.chain[stop].kind.value != EventKind::stop) ++stop;
  if (stop == vehicle.chain.size()) return std::nullopt;
  const std::optional<PlanePoint> place = sign_place(file, *vehicle.end_sign);
  const Approach* way = layout.approach(heading);
  if (!place || !way) return std::nullopt;  // the checks and the heading have said why
  const double dx = place->x - way->entry.x, dy = place->y - way->entry.y;
  const double along = dx * way->direction.x + dy * way->direction.y;
  const double across = std::abs(dx * way->direction.y - dy * way->direction.x);
  const double reach = layout.lanes * layout.lane_width + kRoadside;
  if (across > reach) {
    diagnostics.warning(vehicle.end_sign->location,
                        vehicle.id.text + "'s ENDSIGN lies " +
                            format_number(std::round(across * 10) / 10) +
                            " m from the line of its way in, not beside it: its stop does not aim "
                            "at the sign and stops where its delay puts it");
    return std::nullopt;
  }
  for (std::size_t k = 0; k < stop; ++k) {
    if (keeps_speed_and_way(vehicle.chain[k], k)) continue;
    diagnostics.warning(vehicle.chain[stop].location,
                        vehicle.id.text +
                            "'s stop comes after an event that changes its speed or "
                            "its way: it cannot aim at the ENDSIGN and stops where "
                            "its delay puts it");
    return std::nullopt;
  }
  return StopAim{stop, along};
}

}  // namespace scenfuzz::accident
