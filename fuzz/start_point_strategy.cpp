// StartPointStrategy: the start point leads the first batch; the inner strategy only ever sees
// the results of its own points.
#include "fuzz/start_point_strategy.hpp"

#include "lang/demand.hpp"

namespace scenfuzz {

StartPointStrategy::StartPointStrategy(UnitPoint start, std::unique_ptr<SearchStrategy> inner)
    : start_(std::move(start)), inner_(std::move(inner)) {
  SCENFUZZ_DEMAND(inner_ != nullptr);
}

std::vector<UnitPoint> StartPointStrategy::propose(std::size_t limit) {
  SCENFUZZ_DEMAND(limit >= 1);
  if (started_) {
    std::vector<UnitPoint> points = inner_->propose(limit);
    inner_points_ = points.size();
    return points;
  }
  started_ = true;
  std::vector<UnitPoint> points = {start_};
  if (limit > 1) {
    std::vector<UnitPoint> rest = inner_->propose(limit - 1);
    points.insert(points.end(), rest.begin(), rest.end());
  }
  inner_points_ = points.size() - 1;
  return points;
}

void StartPointStrategy::observe(std::span<const Observation> results) {
  SCENFUZZ_DEMAND(results.size() >= inner_points_);
  if (inner_points_ > 0) inner_->observe(results.subspan(results.size() - inner_points_));
}

}  // namespace scenfuzz
