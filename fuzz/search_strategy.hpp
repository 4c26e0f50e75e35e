// A search strategy proposes points of the unit cube in batches and learns from their results;
// the search loop (search.hpp) evaluates each batch in parallel and feeds the results back in
// the order the points were proposed, so the strategy's course never depends on the thread
// count. Strategies minimise: a finding is any point whose objective is negative.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "sampler/point_samplers.hpp"

namespace scenfuzz {

// What a strategy learns about one point: the robustness of the objective it targets, or +inf
// for a point that was infeasible or could not be judged (never better than a judged point).
struct Observation {
  UnitPoint point;
  double objective = std::numeric_limits<double>::infinity();
  bool judged = false;
};

class SearchStrategy {
 public:
  virtual ~SearchStrategy() = default;
  // Up to `limit` (>= 1) points to evaluate next; an empty batch ends this strategy's search.
  virtual std::vector<UnitPoint> propose(std::size_t limit) = 0;
  // The results of the last batch, one per proposed point and in its order.
  virtual void observe(std::span<const Observation> results) = 0;
};

// --algo NAME: "ga" (default), "random", "halton", "lhs", "nlopt:<ALGORITHM>" (GN_ISRES,
// LN_BOBYQA, ...). Throws std::invalid_argument with a message naming the choices for an unknown
// name. `seed` seeds every random choice of the strategy; `budget` is the number of evaluations
// it will get (strategies may size themselves by it).
std::unique_ptr<SearchStrategy> make_search_strategy(const std::string& algorithm,
                                                     std::span<const SearchDimension> dimensions,
                                                     std::uint64_t seed, std::size_t budget);

// The names --algo accepts, for help texts and error messages.
std::vector<std::string> search_algorithm_names();

}  // namespace scenfuzz
