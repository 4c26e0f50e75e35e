// The sample-count check of the simulation's limits.
#include "physics/simulation/simulation_limits.hpp"

#include <cmath>

#include "lang/number_format.hpp"

namespace scenfuzz {

std::optional<std::string> sample_count_problem(double duration, double dt) {
  if (!std::isfinite(dt) || dt <= 0)
    return "the time step must be a finite number of seconds > 0, not " + format_number(dt);
  if (!std::isfinite(duration) || duration < 0)
    return "the duration must be a finite number of seconds >= 0, not " + format_number(duration);
  // As simulate() counts them: steps 0 .. floor(duration / dt).
  const double samples = std::floor(duration / dt + 1e-9) + 1;
  if (samples > static_cast<double>(kMaxTraceSamples))
    return "a duration of " + format_number(duration) + " s at a time step of " +
           format_number(dt) + " s takes " + format_number(samples) + " samples, more than the " +
           std::to_string(kMaxTraceSamples) + " a trace may hold";
  return std::nullopt;
}

}  // namespace scenfuzz
