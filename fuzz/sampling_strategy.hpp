// The sampling baselines every comparison is made against: uniform random points, the scrambled
// Halton sequence, and Latin hypercube designs. They learn nothing from results and never end by
// themselves; the budget ends them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "fuzz/evaluator.hpp"
#include "fuzz/search_strategy.hpp"

namespace scenfuzz {

// "random": uniform points from one Random seeded by `seed`. "halton": HaltonSequence(d, seed)
// in index order. "lhs": a Latin hypercube design of `budget` points (at least one) proposed in
// order, then a fresh design of the same size, and so on. The points form one sequence whatever
// the batch sizes, so results do not depend on the thread count. propose(limit) returns exactly
// `limit` points; observe() ignores its results. Discrete dimensions need nothing special:
// decode() maps the coordinate to a choice. Throws std::invalid_argument for any other name.
std::unique_ptr<SearchStrategy> make_sampling_strategy(const std::string& name,
                                                       std::span<const SearchDimension> dimensions,
                                                       std::uint64_t seed, std::size_t budget);

}  // namespace scenfuzz
