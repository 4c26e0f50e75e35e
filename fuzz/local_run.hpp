// One local descent from a start point, asked and told one point at a time: NLopt's COBYLA (a
// trust region over linear models of the objective, started with an axis-aligned simplex) on
// the unit cube. The GA runs one from a promising point of each generation: where robustness
// falls smoothly towards a violation, a local model walks down to it in a few simulations,
// which blending and random steps do not (docs/performance.md, "Search").
//
// NLopt calls its objective instead of being asked, and COBYLA is deterministic given the
// start and the values it is told, so every next_point() replays the run from the start on the
// values told so far and stops it at the first point without one. Replaying costs a few
// milliseconds of arithmetic per point, nothing beside a simulation, and needs no thread.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <optional>

#include "sampler/point_samplers.hpp"

namespace scenfuzz {

struct LocalRunOptions {
  // The simplex's first step along every axis, in unit-cube units. 0: NLopt's default for a box,
  // a quarter of the range (less near a bound), which reaches a neighbouring behaviour.
  double initial_step = 0;
  // The run ends once this many points in a row failed to improve its best by more than
  // `improvement` (besides ending when NLopt converges): a local model on a plateau of
  // robustness learns nothing, and the simulations are better spent elsewhere. 0: twice the
  // d + 1 points of a simplex. With d + 1, descents towards a needle of a violation (a ball of
  // radius 0.05 in 6 dimensions) stopped short of it: the GA with descents took a median 346
  // simulations against 161 without them; with twice that, 116.
  std::size_t patience = 0;
  double improvement = 0.02;
  // The run ends after this many points whatever happens.
  std::size_t max_points = 200;
};

// Invariant: `told_` holds exactly the points the run has asked for, with their values, and
// replaying NLopt on them reproduces the same course.
class LocalRun {
 public:
  LocalRun(UnitPoint start, const LocalRunOptions& options = {});
  // A run from a point already evaluated: it does not ask for its start again.
  LocalRun(UnitPoint start, double start_objective, const LocalRunOptions& options = {});

  // The next point to evaluate, or nullopt once the run has ended (converged, out of patience
  // or out of points). Throws std::logic_error when the last point was not told.
  std::optional<UnitPoint> next_point();
  // The objective of the point last returned; NaN and infinities (an infeasible or unjudged
  // point) are worse than every judged value.
  void tell(double objective);

  bool ended() const { return ended_; }
  std::size_t points() const { return told_.size(); }
  // Points told since the last one that improved the run's best by more than `improvement`.
  std::size_t points_without_improvement() const { return points_without_improvement_; }

 private:
  UnitPoint start_;
  LocalRunOptions options_;
  std::map<UnitPoint, double> told_;
  std::optional<UnitPoint> asked_;
  bool ended_ = false;
  double best_ = std::numeric_limits<double>::infinity();
  std::size_t points_without_improvement_ = 0;
};

}  // namespace scenfuzz
