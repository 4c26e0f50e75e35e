// The safe distances of Responsibility-Sensitive Safety (Shalev-Shwartz et al. 2017, definitions
// 1, 2 and 4), as ad-rss-lib computes them: the worst case is that each party keeps accelerating
// for its response time and only then brakes at the least proper rate.
#pragma once

#include "oracle/rss_parameters.hpp"

namespace scenfuzz {

// Metres a vehicle at `speed` covers while it accelerates at `accel` for `response_time` and
// then brakes at `brake` to a stop (its stated braking pattern).
double rss_stopping_distance(double speed, double response_time, double accel, double brake);

// Same direction: the least gap between a rear vehicle at `rear_speed` (response time
// `rear_response_time`) and a front one at `front_speed` that may brake at brake_max. >= 0.
double rss_safe_longitudinal_same(double rear_speed, double front_speed, double rear_response_time,
                                  const RssParameters& rss);

// Opposite directions, each speed towards the other: `correct_speed` on its own lane's direction
// (who brakes at brake_min_correct), `wrong_speed` the one driving against it (brake_min).
double rss_safe_longitudinal_opposite(double correct_speed, double correct_response_time,
                                      double wrong_speed, double wrong_response_time,
                                      const RssParameters& rss);

// How far a party with lateral velocity `towards` (positive towards the other) may come closer
// sideways in the worst case: lateral_accel_max for its response time, then lateral_brake_min
// to zero lateral velocity (negative when it keeps moving away).
double rss_lateral_approach(double towards, double response_time, const RssParameters& rss);

// The least lateral gap: the margin plus both worst-case approaches, never below the margin.
double rss_safe_lateral(double first_towards, double first_response_time, double second_towards,
                        double second_response_time, const RssParameters& rss);

}  // namespace scenfuzz
