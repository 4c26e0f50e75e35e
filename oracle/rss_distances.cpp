// RSS's safe distances. The formulas are the paper's; speeds below zero (a reversing car) count as
// zero where the paper assumes forward motion.
#include "oracle/rss_distances.hpp"

#include <algorithm>
#include <cmath>

namespace scenfuzz {

double rss_stopping_distance(double speed, double response_time, double accel, double brake) {
  const double v = std::max(speed, 0.0);
  const double after_response = v + response_time * accel;
  return v * response_time + 0.5 * accel * response_time * response_time +
         after_response * after_response / (2 * brake);
}

double rss_safe_longitudinal_same(double rear_speed, double front_speed, double rear_response_time,
                                  const RssParameters& rss) {
  const double front = std::max(front_speed, 0.0);
  const double rear =
      rss_stopping_distance(rear_speed, rear_response_time, rss.accel_max, rss.brake_min);
  return std::max(0.0, rear - front * front / (2 * rss.brake_max));
}

double rss_safe_longitudinal_opposite(double correct_speed, double correct_response_time,
                                      double wrong_speed, double wrong_response_time,
                                      const RssParameters& rss) {
  return rss_stopping_distance(correct_speed, correct_response_time, rss.accel_max,
                               rss.brake_min_correct) +
         rss_stopping_distance(wrong_speed, wrong_response_time, rss.accel_max, rss.brake_min);
}

double rss_lateral_approach(double towards, double response_time, const RssParameters& rss) {
  const double after_response = towards + response_time * rss.lateral_accel_max;
  return towards * response_time + 0.5 * rss.lateral_accel_max * response_time * response_time +
         after_response * std::abs(after_response) / (2 * rss.lateral_brake_min);
}

double rss_safe_lateral(double first_towards, double first_response_time, double second_towards,
                        double second_response_time, const RssParameters& rss) {
  const double approach = rss_lateral_approach(first_towards, first_response_time, rss) +
                          rss_lateral_approach(second_towards, second_response_time, rss);
  return rss.lateral_fluctuation_margin + std::max(0.0, approach);
}

}  // namespace scenfuzz
