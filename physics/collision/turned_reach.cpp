// |cos| and |sin| by Cody-Waite reduction to [-pi/4, pi/4] and Taylor polynomials (truncation
// below 1e-11 there), widened by a margin far above their error: a bound, not libm's answer.
#include "physics/collision/turned_reach.hpp"

#include <cmath>

namespace scenfuzz {
namespace {

// pi/2 split so that k * kPiOver2High is exact for |k| < 2^20 (fdlibm's pio2_1, pio2_1t).
constexpr double kPiOver2High = 1.57079632673412561417e+00;
constexpr double kPiOver2Low = 6.07710050650619224932e-11;
constexpr double kTwoOverPi = 0.63661977236758134308;
// Beyond this the reduction loses accuracy; headings there (never seen in practice) use libm.
constexpr double kReducibleHeading = 1e5;
// Relative widening: far above the polynomials' truncation (1e-11), the reduction's and libm's
// errors (~1e-15) and the products' rounding, and a few nanometres on a car: nothing.
constexpr double kRelativeMargin = 1e-9;

struct AbsSinCos {
  double abs_cos = 0, abs_sin = 0;
};

AbsSinCos abs_sin_cos(double heading) {
  if (!(std::abs(heading) < kReducibleHeading))
    return {std::abs(std::cos(heading)), std::abs(std::sin(heading))};
  // Round to nearest by the 1.5 * 2^52 trick: exact below 2^51, and no libm call.
  constexpr double kRoundingShift = 0x1.8p52;
  const double k = (heading * kTwoOverPi + kRoundingShift) - kRoundingShift;
  const double r = (heading - k * kPiOver2High) - k * kPiOver2Low;
  const double r2 = r * r;
  // Horner forms of the Taylor series through r^11 and r^12 (truncation below 1e-11 and 4e-13
  // for |r| <= pi/4, well under kRelativeMargin).
  const double sin_r =
      r * (1 + r2 * (-1.0 / 6 +
                     r2 * (1.0 / 120 +
                           r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800))))));
  const double cos_r =
      1 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 +
                                              r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 +
                                                                        r2 * (1.0 / 479001600))))));
  // An odd number of quarter turns swaps sine and cosine (up to sign, which abs removes).
  const bool odd = (static_cast<long long>(k) & 1) != 0;
  return odd ? AbsSinCos{std::abs(sin_r), std::abs(cos_r)}
             : AbsSinCos{std::abs(cos_r), std::abs(sin_r)};
}

}  // namespace

TurnedReach turned_reach_bound(double half_length, double half_width, double heading) {
  const AbsSinCos t = abs_sin_cos(heading);
  const double margin = kRelativeMargin * (half_length + half_width) + 1e-300;
  return {half_length * t.abs_cos + half_width * t.abs_sin + margin,
          half_length * t.abs_sin + half_width * t.abs_cos + margin};
}

}  // namespace scenfuzz
