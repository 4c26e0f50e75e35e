// Collisions of the ego in words and JSON (collision_report.hpp).
#include "fuzz/collision_report.hpp"

#include <cmath>

#include "fuzz/report_format.hpp"
#include "lang/number_format.hpp"
#include "physics/collision/body_side.hpp"

namespace scenfuzz {

std::string describe_collision(const Trace& trace, const Collision& collision) {
  return "collision at " + format_number(std::round(collision.time * 1000) / 1000) +
         " s: " + trace.actors[collision.first].name + " " +
         std::string(body_side_name(collision.first_side)) + " / " +
         trace.actors[collision.second].name + " " +
         std::string(body_side_name(collision.second_side)) + " at (" +
         format_number(std::round(collision.point.x * 100) / 100) + ", " +
         format_number(std::round(collision.point.y * 100) / 100) + ")";
}

std::string describe_responsibility(const Trace& trace, const CollisionResponsibility& r) {
  const CollisionTriage& t = r.triage;
  const auto tenths = [](double value) { return format_number(std::round(value * 10) / 10); };
  std::string text = "  responsibility: " + std::string(responsibility_name(r.responsibility)) +
                     ": " + r.reason + "\n";
  text += "  triage: ego at " + tenths(t.ego_speed) + " m/s, " + tenths(t.ego_acceleration) +
          " m/s^2" +
          (t.ego_stationary         ? " (stationary)"
           : t.ego_braking_at_limit ? " (braking at its limit)"
                                    : "") +
          "; relative speed " + tenths(t.relative_speed) + " m/s, impact angle " +
          tenths(t.impact_angle) + " deg";
  if (t.entry) {
    text += "; " + trace.actors[r.other].name + " in the ego's path from " + tenths(t.entry->time) +
            " s, gap " + tenths(t.entry->gap) + " m";
    if (std::isfinite(t.entry->time_to_collision))
      text += ", TTC " + tenths(t.entry->time_to_collision) + " s, needing " +
              tenths(t.entry->required_deceleration) + " m/s^2";
  }
  return text;
}

nlohmann::json responsibility_json(const CollisionResponsibility& r) {
  const CollisionTriage& t = r.triage;
  nlohmann::json triage = {
      {"ego_speed", t.ego_speed},           {"ego_acceleration", t.ego_acceleration},
      {"relative_speed", t.relative_speed}, {"impact_angle", t.impact_angle},
      {"ego_stationary", t.ego_stationary}, {"ego_braking_at_limit", t.ego_braking_at_limit}};
  if (t.entry)
    triage["entry"] = {{"time", t.entry->time},
                       {"gap", t.entry->gap},
                       {"closing_speed", t.entry->closing_speed},
                       {"time_to_collision", robustness_json(t.entry->time_to_collision)},
                       {"required_deceleration", robustness_json(t.entry->required_deceleration)},
                       {"from_start", t.entry->from_start}};
  return triage;
}

}  // namespace scenfuzz
