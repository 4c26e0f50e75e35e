#include "fuzz/search_strategy.hpp"

#include <stdexcept>

#include "fuzz/genetic_algorithm.hpp"
#include "fuzz/nlopt_strategy.hpp"
#include "fuzz/sampling_strategy.hpp"

namespace scenfuzz {

namespace {

constexpr std::string_view kNloptPrefix = "nlopt:";

}  // namespace

std::vector<std::string> search_algorithm_names() {
  std::vector<std::string> names = {"ga", "random", "halton", "lhs"};
  for (const std::string& name : nlopt_algorithm_names())
    names.push_back(std::string(kNloptPrefix) + name);
  return names;
}

std::unique_ptr<SearchStrategy> make_search_strategy(const std::string& algorithm,
                                                     std::span<const SearchDimension> dimensions,
                                                     std::uint64_t seed, std::size_t budget) {
  if (algorithm == "ga") return make_genetic_algorithm(dimensions, seed, budget);
  if (algorithm == "random" || algorithm == "halton" || algorithm == "lhs")
    return make_sampling_strategy(algorithm, dimensions, seed, budget);
  if (algorithm.starts_with(kNloptPrefix))
    return make_nlopt_strategy(algorithm.substr(kNloptPrefix.size()), dimensions, seed, budget);
  throw std::invalid_argument("unknown search algorithm '" + algorithm +
                              "'; expected ga, random, halton, lhs or nlopt:NAME (e.g. "
                              "nlopt:GN_ISRES, nlopt:LN_BOBYQA)");
}

}  // namespace scenfuzz
