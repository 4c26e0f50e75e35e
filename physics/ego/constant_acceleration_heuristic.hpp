// Treiber's ACC model (Kesting, Treiber, Helbing 2010, "Enhanced intelligent driver model to
// access the impact of driving strategies on traffic capacity", Phil. Trans. R. Soc. A 368):
// IDM brakes hard whenever the gap is far below its wish, also behind a leader driving away at
// the same speed (the reference driver, finding a car 7 m ahead at 10 m/s, braked at 5.4 m/s^2).
// The constant-acceleration heuristic (CAH) says what braking a collision with a leader keeping its
// speed would actually need; where IDM asks for more, the ACC blends towards the CAH's with a
// smooth limit of one comfortable deceleration, so a gap too small but not closing is opened
// gently. The leader's own acceleration is taken as 0 (the driver does not perceive it); its
// time-to-collision emergency braking still covers a leader that brakes.
#pragma once

#include <cmath>

namespace scenfuzz {

// The ACC acceleration from IDM's `idm` (m/s^2) behind a leader `gap` m ahead (bumper to
// bumper, > 0) moving at `lead_speed` while the follower moves at `speed`.
inline double with_constant_acceleration_heuristic(double idm, double speed, double lead_speed,
                                                   double gap, double comfortable_deceleration) {
  constexpr double kCoolness = 0.99;  // the paper's c
  const double closing = speed - lead_speed;
  const double cah = closing <= 0 ? 0.0 : -closing * closing / (2 * gap);
  if (idm >= cah) return idm;
  const double b = comfortable_deceleration;
  return (1 - kCoolness) * idm + kCoolness * (cah + b * std::tanh((idm - cah) / b));
}

}  // namespace scenfuzz
