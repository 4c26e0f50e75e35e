// The constants of Responsibility-Sensitive Safety (Shalev-Shwartz, Shammah, Shashua 2017) that the
// responsibility oracle judges collisions with. The defaults are Intel ad-rss-lib's starting values
// (intel/ad-rss-lib, doc/ad_rss/Appendix-ParameterDiscussion.md, "Decision on Selected Parameter
// Values"): rho_ego 1 s, rho_other 2 s, accel max 3.5, brake min 4, brake max 8, brake min correct
// 3, lateral brake min 0.8, lateral accel max 0.2 (m/s^2), lateral fluctuation margin 0.1 m.
// `--rss NAME=VALUE` (fuzz/options.def) overrides one of them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scenfuzz {

struct RssParameters {
  double response_time_ego = 1.0;    // s, rho_ego: an automated driver answers fast
  double response_time_other = 2.0;  // s, rho_other: every other road user is taken as human
  double accel_max = 3.5;            // m/s^2, alpha_lon,accel,max during the response time
  double brake_min = 4.0;            // m/s^2, alpha_lon,brake,min: the least proper braking
  double brake_max = 8.0;            // m/s^2, alpha_lon,brake,max: the hardest a leader may brake
  double brake_min_correct = 3.0;    // m/s^2, alpha_lon,brake,min,correct: facing oncoming traffic
  double lateral_accel_max = 0.2;    // m/s^2, alpha_lat,accel,max during the response time
  double lateral_brake_min = 0.8;    // m/s^2, alpha_lat,brake,min: the least proper lateral braking
  double lateral_fluctuation_margin = 0.1;  // m, mu: lateral drift within a lane

  bool operator==(const RssParameters&) const = default;
};

// One parameter as `--rss` names it, with a pointer to its field.
struct RssParameterField {
  std::string_view name;
  double RssParameters::*field;
  std::string_view unit;
};

// Every parameter, in the order above.
const std::vector<RssParameterField>& rss_parameter_fields();

// Applies assignments "NAME=VALUE" (each a parameter of rss_parameter_fields, VALUE a finite
// number > 0, or >= 0 for the margin) to the defaults. Returns the parameters, or the first
// problem in words naming the assignment.
struct RssParametersOrError {
  std::optional<RssParameters> parameters;
  std::string error;
};
RssParametersOrError parse_rss_parameters(const std::vector<std::string>& assignments);

}  // namespace scenfuzz
