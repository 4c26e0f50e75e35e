// A strategy that first proposes one given point, then hands over to another: a concrete seed
// searched by mutation is evaluated as written before anything else, so that a scenario that
// already fails is the search's first finding, whatever the strategy.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "fuzz/search_strategy.hpp"

namespace scenfuzz {

class StartPointStrategy : public SearchStrategy {
 public:
  StartPointStrategy(UnitPoint start, std::unique_ptr<SearchStrategy> inner);

  std::vector<UnitPoint> propose(std::size_t limit) override;
  void observe(std::span<const Observation> results) override;

 private:
  UnitPoint start_;
  std::unique_ptr<SearchStrategy> inner_;
  bool started_ = false;
  std::size_t inner_points_ = 0;  // of the last batch: its last ones are the inner strategy's
};

}  // namespace scenfuzz
