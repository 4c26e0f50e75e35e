#include "fuzz/local_run.hpp"

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <stdexcept>
#include <utility>

#include "fuzz/nlopt_strategy.hpp"

namespace scenfuzz {
namespace {

// Finer steps than this (unit-cube units) rarely change a simulation: NLopt's convergence.
constexpr double converged_step = 1e-4;

// Counts the points since the best last improved by more than `improvement`; a run that only
// creeps down a plateau by millimetres counts as not improving.
void count_improvement(double value, double improvement, double& best,
                       std::size_t& without_improvement) {
  if (value < best - improvement) {
    without_improvement = 0;
  } else {
    ++without_improvement;
  }
  best = std::min(best, value);
}

// One replay: answers NLopt from the values told so far and notes where the run stops.
struct Replay {
  Replay(const std::map<UnitPoint, double>& told_values, const LocalRunOptions& run_options)
      : told(told_values), options(run_options) {}

  const std::map<UnitPoint, double>& told;
  const LocalRunOptions& options;
  std::optional<UnitPoint> unknown;  // the first point without a value
  bool out_of_patience = false;
  double best = std::numeric_limits<double>::infinity();
  std::size_t without_improvement = 0;
  std::size_t calls = 0;

  double value_at(const UnitPoint& point) {
    if (without_improvement >= options.patience || calls >= options.max_points) {
      out_of_patience = true;
      throw nlopt::forced_stop();
    }
    ++calls;
    const auto found = told.find(point);
    if (found == told.end()) {
      unknown = point;
      throw nlopt::forced_stop();
    }
    const double value = found->second;
    count_improvement(value, options.improvement, best, without_improvement);
    return value;
  }

  static double objective(unsigned n, const double* x, double* /*gradient*/, void* data) {
    UnitPoint point(x, x + n);
    for (double& coordinate : point)
      coordinate = std::isnan(coordinate) ? 0.5 : std::clamp(coordinate, 0.0, 1.0);
    return static_cast<Replay*>(data)->value_at(point);
  }
};

}  // namespace

LocalRun::LocalRun(UnitPoint start, const LocalRunOptions& options)
    : start_(std::move(start)), options_(options) {
  for (double& coordinate : start_)
    coordinate = std::isnan(coordinate) ? 0.5 : std::clamp(coordinate, 0.0, 1.0);
  if (options_.patience == 0) options_.patience = 2 * (start_.size() + 1);
  ended_ = start_.empty();
}

LocalRun::LocalRun(UnitPoint start, double start_objective, const LocalRunOptions& options)
    : LocalRun(std::move(start), options) {
  if (ended_) return;
  asked_ = start_;
  tell(start_objective);
}

std::optional<UnitPoint> LocalRun::next_point() {
  if (asked_) throw std::logic_error("LocalRun::next_point called before the last point was told");
  if (ended_) return std::nullopt;
  Replay replay(told_, options_);
  nlopt::opt optimiser(nlopt::LN_COBYLA, static_cast<unsigned>(start_.size()));
  optimiser.set_lower_bounds(0.0);
  optimiser.set_upper_bounds(1.0);
  optimiser.set_xtol_abs(converged_step);
  if (options_.initial_step > 0) optimiser.set_initial_step(options_.initial_step);
  optimiser.set_min_objective(&Replay::objective, &replay);
  UnitPoint x = start_;
  double minimum = 0;
  try {
    optimiser.optimize(x, minimum);
  } catch (const nlopt::forced_stop&) {
  } catch (const std::exception&) {
    // roundoff_limited and NLopt's other failures: the run is over either way.
  }
  if (!replay.unknown || replay.out_of_patience) {
    ended_ = true;
    return std::nullopt;
  }
  asked_ = replay.unknown;
  return asked_;
}

void LocalRun::tell(double objective) {
  if (!asked_) throw std::logic_error("LocalRun::tell called without a point asked for");
  double value = std::isnan(objective) ? nlopt_penalty : objective;
  value = std::clamp(value, -nlopt_penalty, nlopt_penalty);
  count_improvement(value, options_.improvement, best_, points_without_improvement_);
  told_.emplace(std::move(*asked_), value);
  asked_.reset();
}

}  // namespace scenfuzz
